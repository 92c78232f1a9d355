/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
License
    This file is part of dlmfdFoam, an extension of OpenFOAM.

    dlmfdFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <http://www.gnu.org/licenses/>.

Description
    particleDistribution owned, on ranks simulated in one process (K boxes
    of a box decomposition, their messages handed over in memory): 2000
    cubes and spheres, thrown about in a box with a floor and a ceiling,
    periodic across the other two directions, with friction history, give
    the same bits as the whole scene in one system, step after step:
    every particle's position, orientation, velocities, forces, the
    contact histories and the contact count, while particles change
    ranks, contacts cross the boxes' faces, edges and corners and the
    periodic boundaries. The same with subCycling inReach and collisions
    automatic, with boxes narrower than the ghosts' reach, and from a
    scene that rank 0 alone read and handed out.

\*---------------------------------------------------------------------------*/

#include "ownedGranularSteps.H"
#include "boxDecomposition.H"
#include "testInput.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "HashSet.H"

#include <gtest/gtest.h>
#include <map>

using namespace Foam;
using Foam::testInput::parse;

namespace
{

//- The scene: 1000 cubes and 1000 spheres (edge and D 0.01 m) on a
//- jittered lattice in a 0.3 m box, with random velocities and spins
autoPtr<granularSystem> makeScene
(
    const std::string& collisionExtra,
    const std::string& effects,
    const scalar speed
)
{
    const dictionary particleDict = parse
    (
        "shapes { ball { type sphere; D 0.01; } cube { type cube; edge 0.01; } }"
        " materials { glass { density 2500; } }"
    );
    const std::string coeffs = "en 0.7; muc 0.4; kn 2e3; ks 1e3;";
    const dictionary collisionDict = parse
    (
        "contactLaw hookeanStaticFriction; subStepsPerContact 20; "
      + collisionExtra
      + " domain { min (0 0 0); max (0.3 0.3 0.3);"
        " periodic (true true false); }"
        " walls { floor { point (0 0 0); normal (0 0 1); material steel; }"
        " ceiling { point (0 0 0.3); normal (0 0 -1); material steel; } }"
        " pairs { glass-glass {" + coeffs + "} glass-steel {" + coeffs + "} }"
    );
    auto sys = autoPtr<granularSystem>::New
    (
        particleDict, collisionDict, sceneEffects(parse(effects))
    );
    sys->setGravity(vector(0, 0, -9.81));

    // A fixed sequence of pseudo-random numbers in [-1, 1)
    unsigned long long seed = 12345;
    auto random = [&seed]()
    {
        seed = seed*6364136223846793005ULL + 1442695040888963407ULL;
        return scalar(seed >> 11)/scalar(1ULL << 53)*2 - 1;
    };
    const label n = 13;
    const scalar h = 0.3/n;
    label id = 0;
    for (label k = 0; k < 12 && id < 2000; ++k)
    {
        for (label j = 0; j < n && id < 2000; ++j)
        {
            for (label i = 0; i < n && id < 2000; ++i)
            {
                const point x
                (
                    (i + 0.5)*h + 0.002*random(),
                    (j + 0.5)*h + 0.002*random(),
                    (k + 0.5)*h + 0.002*random() + 0.006
                );
                const vector axis(random(), random(), random() + 1.5);
                sys->addParticle
                (
                    id, id % 2 ? "cube" : "ball", "glass", x,
                    quaternion(axis/mag(axis), 3*random())
                );
                ++id;
            }
        }
    }
    sys->updated();
    for (label i = 0; i < sys->size(); ++i)
    {
        sys->particle(i).setVelocity
        (
            speed*vector(random(), random(), random())
        );
        sys->particle(i).setOmega(speed*80*vector(random(), random(), random()));
    }
    if (speed == 0)
    {
        // A scene at rest but for two pairs pressed into each other by 4 %
        // of D, which fling each other apart much farther than anything
        // moves at rest: a ball against a cube's face across x = 0.15 (a
        // face of the boxes), and two cubes face to face across the
        // periodic boundary x = 0
        const scalar y = sys->particle(565).position().y();
        const scalar z = sys->particle(565).position().z();
        sys->particle(565).setOrientation(quaternion::I);
        sys->particle(565).setPosition(point(0.1548, y, z));
        sys->particle(564).setPosition(point(0.1452, y, z));
        const point x923 = sys->particle(923).position();
        sys->particle(923).setOrientation(quaternion::I);
        sys->particle(935).setOrientation(quaternion::I);
        sys->particle(923).setPosition(point(0.0048, x923.y(), x923.z()));
        sys->particle(935).setPosition(point(0.2952, x923.y(), x923.z()));
    }
    return sys;
}


//- Bit for bit the same particle
void expectSameBits
(
    const rigidParticle& a,
    const granularSystem::particleRecord& b,
    const label step
)
{
    const rigidParticle::motionState s = a.state();
    const auto same = [](const vector& u, const vector& v)
    {
        return u.x() == v.x() && u.y() == v.y() && u.z() == v.z();
    };
    EXPECT_TRUE(same(s.x, b.state.x)) << "step " << step << " particle " << b.id;
    EXPECT_TRUE
    (
        s.q.w() == b.state.q.w() && same(s.q.v(), b.state.q.v())
    ) << "step " << step << " particle " << b.id;
    EXPECT_TRUE(same(s.U, b.state.U)) << "step " << step << " particle " << b.id;
    EXPECT_TRUE(same(s.omega, b.state.omega))
        << "step " << step << " particle " << b.id;
    EXPECT_TRUE(same(s.F, b.state.F)) << "step " << step << " particle " << b.id;
    EXPECT_TRUE(same(s.T, b.state.T)) << "step " << step << " particle " << b.id;
}


//- Run the scene whole and on the boxes side by side and compare after
//- every step; returns the contacts over the run
label compareRuns
(
    const labelVector& boxes,
    const std::string& collisionExtra,
    const std::string& effects,
    const label nSteps,
    const label subStepsPerStep,
    const scalar speed,
    label& migrated,
    label& widened
)
{
    auto whole = makeScene(collisionExtra, effects, speed);
    const label K = boxes.x()*boxes.y()*boxes.z();
    PtrList<granularSystem> parts(K);
    for (label k = 0; k < K; ++k)
    {
        parts.set(k, makeScene(collisionExtra, effects, speed).ptr());
    }
    const boxDecomposition decomposition
    (
        whole->domain(), whole->periodic(), boxes
    );
    const virtualRankExchange exchange(K);
    ownedGranularSteps owned
    (
        UPtrList<granularSystem>(parts), decomposition, exchange
    );

    const scalar Deltat = subStepsPerStep*whole->maxSubStep();
    label contacts = 0, ghosts = 0, skipped = 0, inReachSteps = 0;
    label fallbacks = 0;
    migrated = 0;
    widened = 0;
    for (label step = 0; step < nSteps; ++step)
    {
        const label n = whole->evolve(Deltat);
        EXPECT_EQ(owned.evolve(Deltat), n) << "step " << step;
        EXPECT_EQ(owned.stats().nContacts, whole->stats().nContacts)
            << "step " << step;
        contacts += whole->stats().nContacts;
        skipped += whole->stats().contactsSkipped;
        inReachSteps += whole->stats().nInReach >= 0;
        fallbacks += whole->stats().nFallbacks;
        for (const granularSystem& s : owned.systems())
        {
            EXPECT_EQ(s.stats().contactsSkipped, whole->stats().contactsSkipped)
                << "step " << step;
            EXPECT_EQ(s.stats().nFallbacks, whole->stats().nFallbacks)
                << "step " << step;
        }
        // Locality: no record beyond reach; each rank sends one message
        // per neighbour per exchange (the ghosts, each sub-step's states,
        // the migration), so at most (n + 2) per neighbour unless the
        // step was redone with a wider reach
        const ownedGranularSteps::counters& c = owned.lastCounters();
        EXPECT_EQ(c.nFarRecords, 0) << "step " << step;
        if (c.nWiderReach == 0)
        {
            EXPECT_LE(c.maxRankMessages, (n + 2)*c.maxNeighbours)
                << "step " << step;
        }
        migrated += owned.lastCounters().nMigrated;
        widened += owned.lastCounters().nWiderReach;
        ghosts += owned.lastCounters().nGhostsSent;

        const List<granularSystem::particleRecord> records =
            owned.ownedRecords();
        EXPECT_EQ(records.size(), whole->size());
        for (const granularSystem::particleRecord& r : records)
        {
            expectSameBits(whole->particle(r.global), r, step);
        }
        if (::testing::Test::HasFailure())
        {
            break;
        }
    }

    // The particle file written at a write time, the restart: gathered
    // from the ranks, the same bytes as the whole scene's
    {
        auto gathered = makeScene(collisionExtra, effects, speed);
        owned.gatherScene(gathered.get());
        const fileName dir(fileName("ownedGranularStepsTest")/name(K));
        // (the same time folder's name: the files name it)
        whole->writeParticles(dir/"whole"/"0.1");
        gathered->writeParticles(dir/"owned"/"0.1");
        IFstream a(dir/"whole"/"0.1"/"particles");
        IFstream b(dir/"owned"/"0.1"/"particles");
        std::string la, lb;
        label nLines = 0, nDiffer = 0;
        while (a.getLine(la).good() | b.getLine(lb).good())
        {
            ++nLines;
            nDiffer += la != lb;
        }
        EXPECT_GT(nLines, whole->size());
        EXPECT_EQ(nDiffer, 0) << "lines of the particle files differ";
        rmDir(dir);
    }

    // The contacts' histories: each rank's entries of its own particles
    // are the whole scene's, and every entry of the whole scene is held
    std::map<std::pair<label, label>, vector> wholeHistory;
    for (const auto& e : whole->history().entries())
    {
        wholeHistory[{e.first.first(), e.first.second()}] = e.second;
    }
    std::map<std::pair<label, label>, vector> ownedHistory;
    for (const granularSystem& s : owned.systems())
    {
        for (const auto& e : s.history().entries())
        {
            ownedHistory[{e.first.first(), e.first.second()}] = e.second;
        }
    }
    EXPECT_GT(wholeHistory.size(), 0u);
    for (const auto& e : wholeHistory)
    {
        const auto found = ownedHistory.find(e.first);
        EXPECT_TRUE(found != ownedHistory.end())
            << "contact " << e.first.first << ' ' << e.first.second;
        if (found != ownedHistory.end())
        {
            EXPECT_TRUE(found->second == e.second)
                << "contact " << e.first.first << ' ' << e.first.second;
        }
    }
    std::cout << K << " boxes: " << contacts << " contacts, " << migrated
        << " changes of rank, " << ghosts << " ghost copies over "
        << nSteps << " steps; " << skipped << " steps without contact work, "
        << inReachSteps << " with the contact work of the particles in reach"
        << " only, " << fallbacks << " fallbacks, " << widened
        << " steps again with a wider reach" << nl;
    EXPECT_GT(ghosts, 0);
    return contacts;
}

} // End anonymous namespace


TEST(ownedGranularSteps, eightBoxesGiveTheBitsOfTheWholeScene)
{
    label migrated = 0, widened = 0;
    const label contacts = compareRuns
    (
        labelVector(2, 2, 2), "", "", 40, 10, 0.6, migrated, widened
    );
    EXPECT_GT(contacts, 1000);
    EXPECT_GT(migrated, 50);
}


TEST(ownedGranularSteps, narrowBoxesAndInReachAndAutomaticGiveTheSameBits)
{
    // Six boxes along x, 5 cm wide: a particle's ghosts reach two boxes
    // away; subCycling inReach and collisions automatic decided over all
    // ranks
    label migrated = 0, widened = 0;
    const label contacts = compareRuns
    (
        labelVector(6, 1, 1), "subCycling inReach;", "collisions automatic;",
        30, 10, 0.6, migrated, widened
    );
    EXPECT_GT(contacts, 500);
    EXPECT_GT(migrated, 50);
}


TEST(ownedGranularSteps, particlesFlungBeyondTheGhostsReachRedoTheStep)
{
    // At rest but for two pressed pairs that fly apart: beyond subCycling
    // inReach's allowed travel (its fallback) and beyond the ghosts'
    // reach (the step again with twice the reach), the same bits
    label migrated = 0, widened = 0;
    const label contacts = compareRuns
    (
        labelVector(2, 2, 2), "subCycling inReach;", "", 15, 40, 0, migrated,
        widened
    );
    EXPECT_GT(contacts, 0);
    EXPECT_GT(widened, 0);
}


namespace
{

//- Every rank in memory, and once asked, rank 0's ghost records for its
//- neighbour rank 1 sent to rank 5 as well (6 boxes along x: rank 5's box
//- lies beyond those particles' reach, across the periodic boundary)
class injectingExchange
:
    public virtualRankExchange
{
public:

    mutable bool inject = false;

    using virtualRankExchange::virtualRankExchange;

    void exchange(UList<messages>& perRank) const override
    {
        if (inject)
        {
            inject = false;
            messages& m = perRank[0];
            const label a = m.ranks.find(1), b = m.ranks.find(5);
            EXPECT_GE(a, 0);
            EXPECT_GE(b, 0);
            EXPECT_GT(m.out[a].size(), 0);
            m.out[b].append(m.out[a]);
        }
        virtualRankExchange::exchange(perRank);
    }
};

} // End anonymous namespace


TEST(ownedGranularSteps, aRecordBeyondTheReachIsCountedAndDropped)
{
    // The counter that says no rank hears of a particle beyond its reach:
    // records sent where they do not belong are counted (and dropped: the
    // step's bits stay those of the whole scene)
    auto whole = makeScene("", "", 0.6);
    PtrList<granularSystem> parts(6);
    for (label k = 0; k < 6; ++k)
    {
        parts.set(k, makeScene("", "", 0.6).ptr());
    }
    const boxDecomposition decomposition
    (
        whole->domain(), whole->periodic(), labelVector(6, 1, 1)
    );
    const injectingExchange exchange(6);
    ownedGranularSteps owned
    (
        UPtrList<granularSystem>(parts), decomposition, exchange
    );
    const scalar Deltat = 10*whole->maxSubStep();
    for (label step = 0; step < 4; ++step)
    {
        exchange.inject = step == 2;
        whole->evolve(Deltat);
        owned.evolve(Deltat);
        const label far = owned.lastCounters().nFarRecords;
        if (step == 2)
        {
            EXPECT_GT(far, 0);
            std::cout << far << " records beyond reach counted at step 2"
                << nl;
        }
        else
        {
            EXPECT_EQ(far, 0) << "step " << step;
        }
        for (const granularSystem::particleRecord& r : owned.ownedRecords())
        {
            expectSameBits(whole->particle(r.global), r, step);
        }
    }
}


TEST(ownedGranularSteps, aSceneHandedOutByRankZeroGivesTheBitsOfTheWholeScene)
{
    // The start of owned mode without the whole scene on every rank: the
    // scene (with contact histories, written mid-run and read back as a
    // restart) read by rank 0 alone and handed out (scatterScene). Each
    // rank receives its own particles and those named for it, in ascending
    // global index, holds its own only with the histories of their
    // contacts, and the steps give the bits of the whole scene
    auto running = makeScene("", "", 0.6);
    const scalar Deltat = 10*running->maxSubStep();
    for (label step = 0; step < 10; ++step)
    {
        running->evolve(Deltat);
    }
    ASSERT_GT(running->history().entries().size(), 0);
    const fileName dir("ownedGranularStepsScatterTest");
    running->writeParticles(dir/"0.1");
    auto whole = makeScene("", "", 0.6);
    auto read = makeScene("", "", 0.6);
    whole->readParticles(dir/"0.1"/"particles");
    read->readParticles(dir/"0.1"/"particles");
    rmDir(dir);

    const label K = 8;
    const boxDecomposition decomposition
    (
        whole->domain(), whole->periodic(), labelVector(2, 2, 2)
    );
    // Every third particle also to the next rank after its owner
    List<labelList> destinations(read->size());
    forAll(destinations, i)
    {
        if (i % 3 == 0)
        {
            const label owner = decomposition.rankOf(read->particle(i).position());
            destinations[i] = labelList(1, (owner + 1) % K);
        }
    }
    PtrList<granularSystem> parts(K);
    for (label k = 0; k < K; ++k)
    {
        parts.set(k, makeScene("", "", 0.6).ptr());
    }
    const virtualRankExchange exchange(K);
    UPtrList<granularSystem> partList(parts);
    const List<List<granularSystem::particleRecord>> sent
    (
        ownedGranularSteps::scatterScene
        (
            exchange, decomposition, read.get(), destinations, partList
        )
    );
    read.clear();

    // What each rank received and holds
    label nOwned = 0;
    for (label k = 0; k < K; ++k)
    {
        label expected = 0;
        for (label i = 0; i < whole->size(); ++i)
        {
            const label owner =
                decomposition.rankOf(whole->particle(i).position());
            expected += owner == k || destinations[i].found(k);
        }
        EXPECT_EQ(sent[k].size(), expected) << "rank " << k;
        forAll(sent[k], m)
        {
            if (m)
            {
                EXPECT_LT(sent[k][m - 1].global, sent[k][m].global);
            }
            expectSameBits(whole->particle(sent[k][m].global), sent[k][m], 0);
        }
        const granularSystem& s = parts[k];
        labelHashSet own;
        for (label i = 0; i < s.size(); ++i)
        {
            EXPECT_EQ(decomposition.rankOf(s.particle(i).position()), k);
            own.insert(s.globalIndex(i));
        }
        nOwned += s.size();
        for (const auto& e : s.history().entries())
        {
            EXPECT_TRUE
            (
                own.found(e.first.first()) || own.found(e.first.second())
            ) << "rank " << k << " holds the history of contact "
              << e.first.first() << ' ' << e.first.second();
        }
    }
    EXPECT_EQ(nOwned, whole->size());
    // Each contact's history on the owners of both its particles (a pair
    // across ranks is computed on both)
    List<std::map<std::pair<label, label>, vector>> held(K);
    for (label k = 0; k < K; ++k)
    {
        for (const auto& f : parts[k].history().entries())
        {
            held[k][{f.first.first(), f.first.second()}] = f.second;
        }
    }
    label nAcross = 0;
    for (const auto& e : whole->history().entries())
    {
        const label i = e.first.first(), j = e.first.second();
        labelList owners(1, decomposition.rankOf(whole->particle(i).position()));
        if (j >= 0)
        {
            const label rj = decomposition.rankOf(whole->particle(j).position());
            if (rj != owners[0])
            {
                owners.append(rj);
                ++nAcross;
            }
        }
        for (const label r : owners)
        {
            const auto f = held[r].find({i, j});
            EXPECT_TRUE(f != held[r].end() && f->second == e.second)
                << "rank " << r << " lacks the history of contact " << i << ' '
                << j;
        }
    }
    EXPECT_GT(nAcross, 0);

    ownedGranularSteps owned(std::move(partList), decomposition, exchange);
    for (label step = 0; step < 20; ++step)
    {
        EXPECT_EQ(owned.evolve(Deltat), whole->evolve(Deltat));
        EXPECT_EQ(owned.stats().nContacts, whole->stats().nContacts)
            << "step " << step;
        for (const granularSystem::particleRecord& r : owned.ownedRecords())
        {
            expectSameBits(whole->particle(r.global), r, step);
        }
        if (::testing::Test::HasFailure())
        {
            break;
        }
    }
}


// ************************************************************************* //
