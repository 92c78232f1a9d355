/*---------------------------------------------------------------------------*\
  dlmfdFoam: DLM/FD particle-resolved simulation of particulate flows
-------------------------------------------------------------------------------
Description
    main() of every GoogleTest unit test: OpenFOAM's fatal errors throw
    (Foam::error, Foam::IOerror) instead of aborting, so that a test can
    expect them; then all tests run.
\*---------------------------------------------------------------------------*/

#include "error.H"
#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);

    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();

    return RUN_ALL_TESTS();
}
