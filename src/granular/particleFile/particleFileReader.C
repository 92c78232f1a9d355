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

#include "particleFileReader.H"
#include "IStringStream.H"
#include "primitiveEntry.H"
#include "HashTable.H"
#include "error.H"
#include "Time.H"
#include "Pstream.H"
#include "OSspecific.H"

#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::particleFileReader::keywords
({
    "particles", "contacts"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- The character of a punctuation token, '\0' for any other token
    char punctuation(const token& t)
    {
        return t.isPunctuation() ? char(t.pToken()) : '\0';
    }

    //- The bracket that closes an opening one
    char closing(const char open)
    {
        return open == '(' ? ')' : open == '[' ? ']' : '}';
    }

    //- The keywords a particle file may hold, for the messages
    std::string keywordsText()
    {
        std::string list("FoamFile");
        for (const word& key : particleFileReader::keywords)
        {
            list += ", " + key;
        }
        return list;
    }

    //- A directive (#include, #calc, ...): a word starting with '#'
    bool isDirective(const token& t)
    {
        return t.isWord() && !t.wordToken().empty() && t.wordToken()[0] == '#';
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::particleFileReader::checkCharacters(const std::string& text) const
{
    // ASCII text outside comments: OpenFOAM's tokenizer takes control
    // characters and other bytes into words, and some of those end the
    // program without a useful message (a word with a byte >= 128:
    // "invalid fileName"). Comments may hold any text.
    enum { code, lineComment, blockComment } state = code;
    label line = 1;
    const std::size_t n = text.size();
    for (std::size_t k = 0; k < n; ++k)
    {
        const unsigned char u = static_cast<unsigned char>(text[k]);
        const unsigned char next = k + 1 < n ? text[k + 1] : 0;
        if (u == '\n')
        {
            ++line;
            if (state == lineComment)
            {
                state = code;
            }
            continue;
        }
        if (state == lineComment)
        {
            continue;
        }
        if (state == blockComment)
        {
            if (u == '*' && next == '/')
            {
                state = code;
                ++k;
            }
            continue;
        }
        if (u == '/' && next == '/')
        {
            state = lineComment;
            ++k;
            continue;
        }
        if (u == '/' && next == '*')
        {
            state = blockComment;
            ++k;
            continue;
        }
        if
        (
            (u < 0x20 && u != '\t' && u != '\r' && u != '\f')
         || u >= 0x7f
        )
        {
            FatalErrorInFunction
                << name_ << " line " << line << ": character code "
                << label(u) << " is not ASCII text; a particle file is"
                << " ASCII text (any text in comments)" << exit(FatalError);
        }
        if (u == '<' || u == '>')
        {
            // OpenFOAM's tokenizer reads a word such as List<word> as a
            // typed list there and then; a malformed one throws out of it
            // with the list unfreed (tests/fuzz: a run grew to 4 GB).
            // A particle file holds no such lists, nor '<' or '>'
            FatalErrorInFunction
                << name_ << " line " << line << ": character '"
                << char(u) << "' is not taken in a particle file (typed"
                << " lists such as List<word> are not; any text in"
                << " comments)" << exit(FatalError);
        }
    }
}


void Foam::particleFileReader::tokenize(const std::string& text)
{
    IStringStream is(text);
    is.name() = name_;
    is.lineNumber() = 1;    // as a file's (a string stream counts from 0)
    while (true)
    {
        const std::streamoff start = is.stdStream().tellg();
        token t;
        is.read(t);
        if (t.good())
        {
            tokens_.append(std::move(t));
        }
        else if (is.eof())
        {
            return;
        }
        else
        {
            // The text the tokenizer stopped on: its next word
            std::size_t from = start < 0 ? text.size() : std::size_t(start);
            while (from < text.size() && std::isspace(text[from]))
            {
                ++from;
            }
            std::size_t to = from;
            while
            (
                to < text.size() && to - from < 40 && !std::isspace(text[to])
             && !std::strchr("();{}[]", text[to])
            )
            {
                ++to;
            }
            FatalErrorInFunction
                << name_ << " line " << t.lineNumber() << ": cannot read "
                << text.substr(from, to - from).c_str() << " (a number"
                << " beyond double range, or a malformed number or word?)"
                << exit(FatalError);
        }
    }
}


Foam::label Foam::particleFileReader::lineOf(const label k) const
{
    if (tokens_.empty())
    {
        return 1;
    }
    return tokens_[min(k, tokens_.size() - 1)].lineNumber();
}


Foam::word Foam::particleFileReader::readKeyword(HashTable<label>& seen)
{
    const token& t = tokens_[next_];
    const label line = t.lineNumber();
    if (isDirective(t))
    {
        FatalErrorInFunction
            << name_ << " line " << line << ": directive " << t.wordToken()
            << " is not taken in a particle file; write the entries"
            << " themselves (" << keywordsText().c_str() << ')' << exit(FatalError);
    }
    if (t.isWord())
    {
        const word& key = t.wordToken();
        const auto first = seen.cfind(key);
        if (first.found())
        {
            FatalErrorInFunction
                << name_ << " line " << line << ": keyword " << key
                << " is given twice (first at line " << *first << ')'
                << exit(FatalError);
        }
        seen.insert(key, line);
        ++next_;
        return key;
    }
    if (t.isVariable())
    {
        FatalErrorInFunction
            << name_ << " line " << line << ": variable " << t.stringToken().c_str()
            << " is not taken in a particle file; write the entries"
            << " themselves (" << keywordsText().c_str() << ')' << exit(FatalError);
    }
    if (t.isString() && !t.isVerbatim())
    {
        // A quoted keyword is a regular expression to OpenFOAM: a
        // pathological one takes minutes to match (found by tests/fuzz)
        FatalErrorInFunction
            << name_ << " line " << line << ": keyword \""
            << t.stringToken().c_str() << "\" is a pattern (a quoted"
            << " keyword); a particle file has plain keywords only ("
            << keywordsText().c_str() << ')' << exit(FatalError);
    }
    FatalErrorInFunction
        << name_ << " line " << line << ": expected a keyword ("
        << keywordsText().c_str() << "), found " << t.info() << exit(FatalError);
    return word::null;
}


Foam::List<Foam::token> Foam::particleFileReader::readValue
(
    const word& keyword,
    const label keyLine
)
{
    DynamicList<token> value;
    DynamicList<std::pair<char, label>> open;   // brackets, with their lines
    while (true)
    {
        if (next_ >= tokens_.size())
        {
            FatalErrorInFunction
                << name_ << ": keyword " << keyword << " (line " << keyLine
                << "): the file ends before its ';'";
            if (open.size())
            {
                FatalError
                    << "; '" << open.last().first << "' of line "
                    << open.last().second << " is not closed";
            }
            FatalError << exit(FatalError);
        }
        const token& t = tokens_[next_];
        const label line = t.lineNumber();
        const char p = punctuation(t);
        if (p == ';' && open.empty())
        {
            ++next_;
            break;
        }
        if (p == '(' || p == '[' || p == '{')
        {
            open.append(std::make_pair(p, line));
        }
        else if (p == ')' || p == ']' || p == '}')
        {
            if (open.empty())
            {
                FatalErrorInFunction
                    << name_ << " line " << line << ": keyword " << keyword
                    << " (line " << keyLine << "): '" << p
                    << "' closes nothing (a ';' missing before it?)"
                    << exit(FatalError);
            }
            if (closing(open.last().first) != p)
            {
                FatalErrorInFunction
                    << name_ << " line " << line << ": keyword " << keyword
                    << ": '" << p << "' does not close '"
                    << open.last().first << "' of line "
                    << open.last().second << exit(FatalError);
            }
            open.remove();
        }
        else if (isDirective(t) || t.isVariable() || t.isVerbatim())
        {
            FatalErrorInFunction
                << name_ << " line " << line << ": keyword " << keyword
                << ": " << t.info() << " is not taken in a particle file"
                << " (no directives, variables or verbatim text)"
                << exit(FatalError);
        }
        value.append(t);
        ++next_;
    }
    if (value.empty())
    {
        FatalErrorInFunction
            << name_ << " line " << keyLine << ": keyword " << keyword
            << " has no value" << exit(FatalError);
    }
    return List<token>(std::move(value));
}


void Foam::particleFileReader::readBlock
(
    const word& keyword,
    const label keyLine
)
{
    HashTable<label> seen;
    while (true)
    {
        if (next_ >= tokens_.size())
        {
            FatalErrorInFunction
                << name_ << ": " << keyword << " (line " << keyLine
                << "): the file ends before its '}'" << exit(FatalError);
        }
        if (tokens_[next_] == token::END_BLOCK)
        {
            ++next_;
            return;
        }
        const label line = lineOf(next_);
        const word key(readKeyword(seen));
        if (next_ < tokens_.size() && tokens_[next_] == token::BEGIN_BLOCK)
        {
            FatalErrorInFunction
                << name_ << " line " << line << ": " << keyword << " entry "
                << key << " is a sub-dictionary; " << keyword
                << " holds plain values only" << exit(FatalError);
        }
        readValue(key, line);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleFileReader::particleFileReader
(
    const std::string& text,
    const fileName& name
)
:
    name_(name),
    tokens_(),
    next_(0)
{
    checkCharacters(text);
    tokenize(text);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dictionary Foam::particleFileReader::entries()
{
    dictionary dict;
    dict.name() = name_;
    HashTable<label> seen;
    next_ = 0;
    while (next_ < tokens_.size())
    {
        const label line = lineOf(next_);
        const word key(readKeyword(seen));
        if (key == "FoamFile")
        {
            if (next_ >= tokens_.size() || tokens_[next_] != token::BEGIN_BLOCK)
            {
                FatalErrorInFunction
                    << name_ << " line " << line << ": expected '{' after"
                    << " FoamFile (the header is a sub-dictionary)"
                    << exit(FatalError);
            }
            ++next_;
            readBlock(key, line);
            continue;
        }
        if (!keywords.found(key))
        {
            FatalErrorInFunction
                << name_ << " line " << line << ": keyword " << key
                << " is not one of " << keywordsText().c_str() << exit(FatalError);
        }
        auto* e = new primitiveEntry(key, readValue(key, line));
        // Named as OpenFOAM names an entry: its messages say <file>.<key>
        e->ITstream::name() = name_ + '.' + key;
        dict.add(e);
    }
    return dict;
}


Foam::dictionary Foam::particleFileReader::read(const fileName& file)
{
    std::ifstream ifs(file, std::ios::binary);
    if (!ifs.good())
    {
        FatalErrorInFunction
            << "cannot open the particle file " << file
            << exit(FatalError);
    }
    std::ostringstream text;
    text << ifs.rdbuf();
    return parse(text.str(), file);
}


Foam::dictionary Foam::particleFileReader::parse
(
    const std::string& text,
    const fileName& name
)
{
    return particleFileReader(text, name).entries();
}


Foam::fileName Foam::particleFileReader::startFile(const Time& runTime)
{
    const fileName written(runTime.timePath()/"uniform"/"particles");
    const fileName given
    (
        runTime.globalPath()/runTime.timeName()/"particles"
    );
    const fileName file(isFile(written) ? written : given);
    if (!isFile(file))
    {
        FatalErrorInFunction
            << "no particle file " << written << " nor " << given << nl
            << "    Place particles with placeParticles, or copy them"
            << " from 0.orig" << exit(FatalError);
    }
    return file;
}


Foam::dictionary Foam::particleFileReader::readStartOnEveryRank
(
    const Time& runTime,
    fileName& file
)
{
    dictionary dict;
    if (Pstream::master())
    {
        file = startFile(runTime);
        dict = read(file);
    }
    Pstream::scatter(file);
    Pstream::scatter(dict);
    return dict;
}


// ************************************************************************* //
