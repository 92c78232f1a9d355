/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

\*---------------------------------------------------------------------------*/

#include "knownKeywords.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "entry.H"
#include "DynamicList.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * * //

Foam::label Foam::knownKeywords::distance
(
    const std::string& a,
    const std::string& b
)
{
    // One row of the dynamic programme at a time
    labelList row(b.size() + 1);
    forAll(row, j)
    {
        row[j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i)
    {
        label diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const label above = row[j];
            row[j] = min
            (
                min(row[j] + 1, row[j - 1] + 1),
                diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)
            );
            diagonal = above;
        }
    }
    return row[b.size()];
}


Foam::wordList Foam::knownKeywords::written
(
    const dictionary& dict,
    const word& subDict,
    const fileName& dictFile,
    labelList* lines
)
{
    // The file given, or else the top-level dictionary's name (a file's
    // path when it was read from one in serial)
    const fileName file
    (
        dictFile.empty() ? fileName(dict.topDict().name()) : dictFile
    );
    DynamicList<word> options;
    DynamicList<label> at;
    const auto collect = [&](const dictionary* scope)
    {
        if (!scope)
        {
            return;
        }
        for (const entry& e : *scope)
        {
            const word& k = e.keyword();
            if (!k.empty() && k[0] != '#' && k != "FoamFile")
            {
                options.append(k);
                at.append(e.startLineNumber());
            }
        }
    };
    // The sub-dictionary named by a path a/b/c below a dictionary
    const auto descend = [&subDict](const dictionary& top)
    {
        const dictionary* scope = &top;
        for (const word& part : subDict.empty() ? wordList() : fileName(subDict).components())
        {
            scope = scope ? scope->findDict(part) : nullptr;
        }
        return scope;
    };
    if (isFile(file))
    {
        // With directives off, "#include" stays an entry of its own and
        // $variables stay unexpanded
        const int directives = entry::disableFunctionEntries;
        entry::disableFunctionEntries = 1;
        IFstream is(file);
        const dictionary raw(is);
        entry::disableFunctionEntries = directives;
        collect(descend(raw));
    }
    else
    {
        collect(descend(dict));
    }
    if (lines)
    {
        *lines = at;
    }
    return wordList(std::move(options));
}


void Foam::knownKeywords::require
(
    const dictionary& dict,
    const wordList& known,
    const word& subDict,
    const fileName& dictFile
)
{
    // In parallel the master read the file and the other ranks got its
    // expanded contents (named IOstream): the master checks for all, its
    // fatal error stops every rank
    if (!Pstream::master())
    {
        return;
    }
    DynamicList<word> variables;
    labelList lines;
    const wordList keys(written(dict, subDict, dictFile, &lines));
    forAll(keys, i)
    {
        const word& key = keys[i];
        if (known.found(key))
        {
            continue;
        }
        word nearest;
        label best = labelMax;
        for (const word& k : known)
        {
            const label d = distance(key, k);
            if (d < best)
            {
                best = d;
                nearest = k;
            }
        }
        // At the top level a keyword far from every known one is taken as
        // a variable ($name), as foamDictionary writes those of an
        // included file (galileoScales) into the file it edits
        const label nearMiss = max(label(2), label(nearest.size()/4));
        if (subDict.empty() && best > nearMiss)
        {
            variables.append(key);
            continue;
        }
        const std::string scope =
            subDict.empty() ? std::string() : " in " + subDict;
        const std::string whose =
            subDict.empty() ? std::string("there") : "of " + subDict;
        // Name the nearest keyword only where it is a plausible misspelling
        const std::string guess =
            best <= nearMiss
          ? " (a misspelling of " + nearest + "?)"
          : std::string();
        FatalIOErrorInFunction(dict)
            << "unknown keyword " << key << scope.c_str() << " of "
            << (dictFile.empty() ? dict.topDict().name() : dictFile).c_str()
            << ", line " << lines[i] << guess.c_str() << "; the keywords "
            << whose.c_str() << " are " << known << exit(FatalIOError);
    }
    if (variables.size())
    {
        Info<< "Entries of "
            << (dictFile.empty() ? dict.topDict().name() : dictFile).c_str()
            << " taken as variables, not options: " << variables << endl;
    }
}


// ************************************************************************* //
