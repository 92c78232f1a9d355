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

#include "rotationTranslationCorrelation.H"
#include "suspensionInput.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- The largest magnitude of the samples, at least SMALL
    Foam::scalar halfRange(const std::vector<Foam::scalar>& v)
    {
        Foam::scalar a = 0;
        for (const Foam::scalar x : v)
        {
            a = Foam::max(a, Foam::mag(x));
        }
        return Foam::max(a, Foam::SMALL);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rotationTranslationCorrelation::rotationTranslationCorrelation
(
    const std::vector<scalar>& omegaX,
    const std::vector<scalar>& Vy,
    const label nBins
)
:
    pearson_(0),
    ax_(halfRange(omegaX)),
    ay_(halfRange(Vy)),
    wx_(2*ax_/nBins),
    wy_(2*ay_/nBins),
    count_(nBins, labelList(nBins, Zero)),
    nSamples_(omegaX.size())
{
    const label n = nSamples_;
    scalar mx = 0, my = 0;
    for (label i = 0; i < n; ++i)
    {
        mx += omegaX[i];
        my += Vy[i];
    }
    mx /= n;
    my /= n;
    scalar sxy = 0, sxx = 0, syy = 0;
    for (label i = 0; i < n; ++i)
    {
        sxy += (omegaX[i] - mx)*(Vy[i] - my);
        sxx += sqr(omegaX[i] - mx);
        syy += sqr(Vy[i] - my);
    }
    pearson_ = sxy/std::sqrt(max(sxx*syy, VSMALL));

    for (label i = 0; i < n; ++i)
    {
        const label bx = min(label((omegaX[i] + ax_)/wx_), nBins - 1);
        const label by = min(label((Vy[i] + ay_)/wy_), nBins - 1);
        ++count_[bx][by];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rotationTranslationCorrelation::write(const fileName& outDir) const
{
    suspensionInput::csvFile os
    (
        outDir/"OmegaX_Vy_jointPdf.csv", "OmegaX_tg,Vy_ug,pdf"
    );
    const label nBins = count_.size();
    for (label bx = 0; bx < nBins; ++bx)
    {
        for (label by = 0; by < nBins; ++by)
        {
            os() << -ax_ + (bx + 0.5)*wx_ << ',' << -ay_ + (by + 0.5)*wy_
                << ',' << count_[bx][by]/(wx_*wy_*scalar(nSamples_)) << nl;
        }
    }
}


// ************************************************************************* //
