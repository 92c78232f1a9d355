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

#include "settlingSeries.H"
#include "mathematicalConstants.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::settlingSeries::settlingSeries
(
    const suspensionScales& sc,
    const suspensionInput::series& steps,
    const scalar tStart,
    const fileName& outDir
)
:
    sumVs_(0),
    sumVarZ_(0),
    sumVarH_(0),
    sumDrag_(0),
    sumOmegaH_(0),
    nWindow_(0)
{
    suspensionInput::csvFile ts
    (
        outDir/"timeSeries.csv",
        "t_tg,Vs_ug,Re,varV_vertical_Vs2,varV_horizontal_Vs2,"
        "anisotropy,OmegaH_tg,drag_over_Stokes"
    );
    for (const auto& step : steps)
    {
        const std::vector<suspensionInput::sample>& s = step.second;
        const label n = s.size();
        const bool inWindow = step.first >= tStart;
        vector meanV(Zero);
        scalar meanOmegaH = 0, meanF = 0;
        for (const suspensionInput::sample& p : s)
        {
            meanV += p.V;
            const scalar oh = mag(p.omega - (p.omega & sc.eg)*sc.eg);
            meanOmegaH += oh;
            meanF += p.F & sc.up;
            if (inWindow)
            {
                omegaH_.push_back(oh*sc.tg);
                omegaX_.push_back(p.omega[sc.hx]*sc.tg);
                Vy_.push_back(p.V[sc.hy]/sc.ug);
            }
        }
        meanV /= n;
        meanOmegaH /= n;
        meanF /= n;
        scalar varZ = 0, varH = 0;
        for (const suspensionInput::sample& p : s)
        {
            const vector d = p.V - meanV;
            varZ += sqr(d[sc.vert]);
            varH += 0.5*(sqr(d[sc.hx]) + sqr(d[sc.hy]));
        }
        varZ /= n;
        varH /= n;
        const scalar Vs = meanV & sc.eg;
        const scalar Vs2 = max(sqr(Vs), VSMALL);
        const scalar drag = meanF/(3*pi*sc.mu*sc.D*Vs + VSMALL);
        ts() << step.first/sc.tg << ',' << Vs/sc.ug << ',' << Vs*sc.D/sc.nu
            << ',' << varZ/Vs2 << ',' << varH/Vs2 << ','
            << varZ/max(varH, VSMALL) << ',' << meanOmegaH*sc.tg << ','
            << drag << nl;

        if (inWindow)
        {
            ++nWindow_;
            sumVs_ += Vs;
            sumVarZ_ += varZ;
            sumVarH_ += varH;
            sumDrag_ += meanF;
            sumOmegaH_ += meanOmegaH;
        }
    }
}


// ************************************************************************* //
