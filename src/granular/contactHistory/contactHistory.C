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

#include "contactHistory.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::contactHistory::force
(
    const contactLaw& law,
    const contactGeometry& c,
    const vector& Urel,
    const scalar M,
    const scalar dt,
    const label i,
    const label j
)
{
    if (!law.needsHistory())
    {
        vector unused(Zero);
        return law.force(c.overlap, c.normal, Urel, M, dt, unused);
    }

    const std::uint64_t k = key(i, j);
    vector h(Zero);
    const auto iter = history_.find(k);
    if (iter != history_.end())
    {
        h = iter->second;
    }
    const vector F = law.force(c.overlap, c.normal, Urel, M, dt, h);
    historyNew_[k] = h;
    return F;
}


void Foam::contactHistory::endSubStep()
{
    history_.swap(historyNew_);
    historyNew_.clear();
}


Foam::List<std::pair<Foam::labelPair, Foam::vector>>
Foam::contactHistory::entries() const
{
    List<std::pair<std::uint64_t, vector>> sorted
    (
        history_.begin(), history_.end()
    );
    std::sort
    (
        sorted.begin(), sorted.end(),
        [](const auto& a, const auto& b){ return a.first < b.first; }
    );
    List<std::pair<labelPair, vector>> result(sorted.size());
    forAll(sorted, n)
    {
        const std::uint64_t k = sorted[n].first;
        result[n].first = labelPair
        (
            label(std::int32_t(k >> 32)),
            label(std::int32_t(k & 0xffffffffu))
        );
        result[n].second = sorted[n].second;
    }
    return result;
}


// ************************************************************************* //
