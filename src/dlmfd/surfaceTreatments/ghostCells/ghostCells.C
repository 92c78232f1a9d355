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

#include "ghostCells.H"
#include "fictitiousDomain.H"
#include "OStringStream.H"
#include "linear.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace surfaceTreatments
{
    defineTypeNameAndDebug(ghostCells, 0);
    addToRunTimeSelectionTable(surfaceTreatment, ghostCells, dictionary);
}
}


const Foam::Enum<Foam::surfaceTreatments::ghostCells::shearModel>
Foam::surfaceTreatments::ghostCells::shearModelNames
({
    {shearModel::viscous, "viscous"},
    {shearModel::link, "link"},
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceTreatments::ghostCells::ghostCells
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    surfaceTreatment(mesh),
    shear_(shearModelNames.getOrDefault("ghostShear", dict, shearModel::link)),
    fitRadius_(dict.getOrDefault<scalar>("ghostFitRadius", 1.5)),
    links_(mesh, shear_ == shearModel::link)
{
    if (!(fitRadius_ >= 1.5))
    {
        FatalIOErrorInFunction(dict)
            << "ghostFitRadius = " << fitRadius_ << " is not"
            << " allowed; it must be >= 1.5 (in cell sizes)"
            << exit(FatalIOError);
    }
    // The links fit nothing: a fit radius would be ignored
    if
    (
        shear_ == shearModel::link
     && dict.found("ghostFitRadius", keyType::LITERAL)
    )
    {
        FatalIOErrorInFunction(dict)
            << "fictitiousDomain/ghostFitRadius is read with ghostShear"
            << " viscous only; this dictionary selects ghostShear link,"
            << " which fits nothing. Remove the entry or select ghostShear"
            << " viscous" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::surfaceTreatments::ghostCells::mirroredShear
(
    const volScalarField& nu,
    const volScalarField& owner,
    const volVectorField& mirror
) const
{
    tmp<volVectorField> tsrc
    (
        new volVectorField
        (
            IOobject("wallShearSource", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedVector(dimAcceleration, Zero)
        )
    );
    vectorField& src = tsrc.ref().primitiveFieldRef();
    const scalarField& V = mesh_.V();
    const surfaceScalarField nuf(linearInterpolate(nu));
    const surfaceScalarField& dc = mesh_.deltaCoeffs();
    const surfaceScalarField& magSf = mesh_.magSf();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& body = owner.primitiveField();
    const vectorField& t = mirror.primitiveField();

    // A face between a body's cell g (t_g) and a fluid cell c: the flux
    // nu |S_f| t_g/|d_f| into c, out of g
    forAll(nei, f)
    {
        const label o = own[f], n = nei[f];
        const bool oBody = body[o] >= 0, nBody = body[n] >= 0;
        if (oBody == nBody)
        {
            continue;
        }
        const label g = oBody ? o : n, c = oBody ? n : o;
        const vector F = nuf[f]*magSf[f]*dc[f]*t[g];
        src[c] += F/V[c];
        src[g] -= F/V[g];
    }

    // Across processor and periodic patches each side takes its own cell's
    // share, with the neighbour's values of the other side
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled())
        {
            continue;
        }
        const labelUList& fc = p.faceCells();
        const scalarField bodyNbr
        (
            owner.boundaryField()[patchi].patchNeighbourField()
        );
        const vectorField tNbr
        (
            mirror.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField& nup = nuf.boundaryField()[patchi];
        const scalarField& dcp = dc.boundaryField()[patchi];
        const scalarField& magSp = magSf.boundaryField()[patchi];
        forAll(fc, i)
        {
            const label l = fc[i];
            const bool lBody = body[l] >= 0, nBody = bodyNbr[i] >= 0;
            if (lBody == nBody)
            {
                continue;
            }
            const scalar coeff = nup[i]*magSp[i]*dcp[i]/V[l];
            if (lBody)
            {
                src[l] -= coeff*t[l];
            }
            else
            {
                src[l] += coeff*tNbr[i];
            }
        }
    }
    tsrc.ref().correctBoundaryConditions();
    return tsrc;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::surfaceTreatments::ghostCells::reach() const
{
    // The fits' largest radius about a surface point (with ghostShear
    // link, whose cells move rigidly, the claims and the clearance across
    // a period keep this margin: the links reach no further)
    return fitRadius_;
}


Foam::scalar Foam::surfaceTreatments::ghostCells::holderCells() const
{
    // The links reach two faces beyond a body's cell (a fluid cell and the
    // third point of its profile), and a cell of travel
    return shear_ == shearModel::link ? max(fitRadius_, scalar(3)) : fitRadius_;
}


bool Foam::surfaceTreatments::ghostCells::readsFluidNearSurface() const
{
    return shear_ == shearModel::viscous;
}


bool Foam::surfaceTreatments::ghostCells::mirrorsWallVelocity() const
{
    return shear_ == shearModel::viscous;
}


Foam::tmp<Foam::fvVectorMatrix>
Foam::surfaceTreatments::ghostCells::fluidStepTerms
(
    const volVectorField& U,
    const volScalarField& nu,
    const UList<fictitiousDomainBody>& bodies,
    const fictitiousDomain& fd
)
{
    if (shear_ == shearModel::link)
    {
        // The wall's shear along the links the surfaces cut, in place of
        // the Laplacian's there
        links_.update(fd.ghostOwner(), bodies, fd.images());
        return links_.matrix(U, nu);
    }
    // The mirrored wall shear on the viscous fluxes to the fluid
    // neighbours, an explicit source (the matrix of "UEqn -= source")
    tmp<fvVectorMatrix> tm
    (
        new fvVectorMatrix(U, U.dimensions()*dimVol/dimTime)
    );
    const tmp<volVectorField> tsrc(mirroredShear(nu, fd.ghostOwner(), fd.mirror()));
    tm.ref().source() += mesh_.V()*tsrc().field();
    return tm;
}


bool Foam::surfaceTreatments::ghostCells::hasFluidGain() const
{
    return shear_ == shearModel::link;
}


void Foam::surfaceTreatments::ghostCells::fluidGain
(
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff,
    fictitiousDomain& fd,
    const UList<fictitiousDomainBody>& bodies,
    const bool perRank,
    const label nScene,
    List<vector>& momentum,
    List<vector>& moment
)
{
    if (shear_ != shearModel::link)
    {
        return;
    }
    // What the fluid gained at the links in its step (with what the time
    // scheme's history carries of the last step)
    if (perRank)
    {
        // Among the holders of each body: the master pays the history of
        // the bodies it holds, the solver of each other body adds the
        // master's share
        Map<vector> masterOwed, masterOwedMoment;
        links_.payAmongHolders
        (
            U, dt, ddtCoeff, fd, bodies, momentum, moment, masterOwed,
            masterOwedMoment, nScene
        );
        fd.setMasterOwed(std::move(masterOwed), std::move(masterOwedMoment));
    }
    else
    {
        links_.pay(U, dt, ddtCoeff, momentum, moment);
    }
}


Foam::string
Foam::surfaceTreatments::ghostCells::outerCorrectorsRefusal() const
{
    if (shear_ != shearModel::link)
    {
        return string();
    }
    return
        "ghostShear link (the default); it must be 1, or select ghostShear"
        " viscous for the outer loop (the links' momentum account is not"
        " made for it)";
}


Foam::wordList Foam::surfaceTreatments::ghostCells::keywords() const
{
    return wordList({"ghostShear", "ghostFitRadius"});
}


Foam::string Foam::surfaceTreatments::ghostCells::describe() const
{
    OStringStream os;
    os  << "surfaceTreatment ghostCells, ghostShear "
        << shearModelNames[shear_];
    if (shear_ == shearModel::viscous)
    {
        os  << ", ghostFitRadius " << fitRadius_;
    }
    return os.str();
}


// ************************************************************************* //
