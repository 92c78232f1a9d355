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

#include "pairDistribution.H"
#include "mathematicalConstants.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pairDistribution::pairDistribution
(
    const suspensionScales& sc,
    const granularSystem& granular,
    const suspensionInput::series& steps,
    const scalar tStart,
    const label interval
)
:
    dr_(0.1*sc.D),
    nr_(0),
    nTheta_(60),
    nSamples_(0),
    norm_(0)
{
    scalar rMax = GREAT;
    for (direction d = 0; d < 3; ++d)
    {
        rMax =
            min(rMax, 0.5*(sc.period[d] > 0 ? sc.period[d] : sc.box.span()[d]));
    }
    nr_ = label(rMax/dr_);
    const scalar dTheta = pi/nTheta_;
    count_.setSize(nr_, labelList(nTheta_, Zero));
    label k = 0;
    for (const auto& step : steps)
    {
        if (step.first < tStart || (k++ % interval) != 0)
        {
            continue;
        }
        ++nSamples_;
        const std::vector<suspensionInput::sample>& s = step.second;
        for (size_t i = 0; i < s.size(); ++i)
        {
            for (size_t j = i + 1; j < s.size(); ++j)
            {
                const vector d = granular.separation(s[j].x, s[i].x);
                const scalar r = mag(d);
                const label br = label(r/dr_);
                if (br >= nr_ || r == 0)
                {
                    continue;
                }
                // From i to j and from j to i (theta and pi - theta)
                const scalar c = max(-1.0, min(1.0, (d & sc.up)/r));
                const label bt =
                    min(label(std::acos(c)/dTheta), nTheta_ - 1);
                ++count_[br][bt];
                ++count_[br][nTheta_ - 1 - bt];
            }
        }
    }
    const scalar density = sc.Np/sc.boxVolume;
    norm_ = scalar(sc.Np)*density*max(nSamples_, 1);
    Info<< "Pair distribution: " << nSamples_ << " samples, r up to "
        << rMax/sc.D << " D" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pairDistribution::write(const fileName& outDir, const scalar D)
const
{
    const scalar dTheta = pi/nTheta_;
    suspensionInput::csvFile pd(outDir/"pairDistribution.csv", "r_D,theta,P");
    suspensionInput::csvFile rd(outDir/"radialDistribution.csv", "r_D,g");
    for (label br = 0; br < nr_; ++br)
    {
        const scalar r0 = br*dr_, r1 = r0 + dr_;
        const scalar shell = 4*pi/3*(pow3(r1) - pow3(r0));
        label total = 0;
        for (label bt = 0; bt < nTheta_; ++bt)
        {
            const scalar t0 = bt*dTheta, t1 = t0 + dTheta;
            const scalar vol =
                2*pi/3*(pow3(r1) - pow3(r0))*(std::cos(t0) - std::cos(t1));
            pd() << (r0 + 0.5*dr_)/D << ',' << t0 + 0.5*dTheta << ','
                << count_[br][bt]/(norm_*vol) << nl;
            total += count_[br][bt];
        }
        rd() << (r0 + 0.5*dr_)/D << ',' << total/(norm_*shell) << nl;
    }
}


// ************************************************************************* //
