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

#include "omegaHDistribution.H"
#include "suspensionInput.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::omegaHDistribution::omegaHDistribution
(
    const std::vector<scalar>& samples,
    const label nBins
)
:
    width_
    (
        max(*std::max_element(samples.begin(), samples.end()), SMALL)/nBins
    ),
    count_(nBins, Zero),
    nSamples_(samples.size())
{
    for (const scalar o : samples)
    {
        ++count_[min(label(o/width_), nBins - 1)];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::omegaHDistribution::write(const fileName& outDir) const
{
    suspensionInput::csvFile os(outDir/"OmegaH_pdf.csv", "OmegaH_tg,pdf");
    forAll(count_, b)
    {
        os() << (b + 0.5)*width_ << ','
            << count_[b]/(width_*scalar(nSamples_)) << nl;
    }
}


// ************************************************************************* //
