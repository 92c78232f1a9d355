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

#include "restartableTime.H"
#include "IFstream.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "dictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

volatile std::sig_atomic_t Foam::restartableTime::stopSignal_ = 0;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::restartableTime::noteSignal(int sig)
{
    stopSignal_ = sig;
}


void Foam::restartableTime::catchSignals()
{
    struct sigaction action;
    action.sa_handler = noteSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;
    for (const int sig : {SIGINT, SIGTERM, SIGUSR1})
    {
        if (sigaction(sig, &action, nullptr) < 0)
        {
            FatalErrorInFunction
                << "cannot set the handler of signal " << sig
                << exit(FatalError);
        }
    }
}


void Foam::restartableTime::findStartFolder()
{
    // Time looks for a start folder named at a raised precision from the
    // largest precision down, and stops where two precisions name the value
    // alike: a value that prints alike at 18 and 17 digits (81.10424886015
    // read back as 81.104248860149994) is never tried at 13 to 16 digits,
    // and the run would start from a folder that does not exist. Search
    // upwards from the precision in use instead
    if (fileHandler().exists(timePath(), false))
    {
        return;
    }
    const int oldPrecision = precision_;
    int p = oldPrecision + 1;
    for (; p <= maxPrecision_; ++p)
    {
        precision_ = p;
        setTime(startTime_, 0);
        if (fileHandler().exists(timePath(), false))
        {
            break;
        }
    }
    if (p > maxPrecision_)
    {
        precision_ = oldPrecision;
        setTime(startTime_, 0);
        return;
    }
    Info<< "Time precision raised from " << oldPrecision << " to " << p
        << " to find the start time's folder " << timeName() << nl << endl;

    // What Time reads from the start folder once it has found it
    IOdictionary timeDict
    (
        IOobject
        (
            "time",
            timeName(),
            "uniform",
            *this,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    if
    (
        controlDict().getOrDefault("adjustTimeStep", false)
     && timeDict.readIfPresent("deltaT", deltaT_)
    )
    {
        deltaTSave_ = deltaT_;
        deltaT0_ = deltaT_;
    }
    timeDict.readIfPresent("deltaT0", deltaT0_);
    if (timeDict.readIfPresent("index", startTimeIndex_))
    {
        timeIndex_ = startTimeIndex_;
    }
}


void Foam::restartableTime::restoreState()
{
    const fileName file(timePath()/"uniform"/"restartState");
    if (!isFile(file))
    {
        return;
    }
    IFstream is(file);
    const dictionary dict(is);
    const string name(dict.get<string>("name"));
    if (name != timeName())
    {
        WarningInFunction
            << file << " belongs to time " << name.c_str()
            << ", not to " << timeName() << ": not restored; the restart"
            << " continues, not bitwise" << endl;
        return;
    }
    // The folder's name is the stored value at a precision that a run may
    // have raised (a write off the time grid of timePrecision); Time raises
    // it to its largest to find that folder, where the exact value would be
    // named otherwise: keep the least precision from timePrecision up (or
    // below it, were it lowered since) that gives the folder's name
    const scalar exactValue = dict.get<scalar>("value");
    const int timePrecision =
        controlDict().getOrDefault<int>("timePrecision", 6);
    auto names = [&](int p) { return Time::timeName(exactValue, p) == name; };
    int p = timePrecision;
    while (p < maxPrecision_ && !names(p))
    {
        ++p;
    }
    if (!names(p))
    {
        p = 1;
        while (p < timePrecision && !names(p))
        {
            ++p;
        }
    }
    precision_ = p;
    setTime(exactValue, timeIndex());
    if (timeName() != name)
    {
        FatalErrorInFunction
            << file << ": no time precision names the value " << exactValue
            << " \"" << name.c_str() << "\"" << exit(FatalError);
    }
    if (controlDict().getOrDefault("adjustTimeStep", false))
    {
        deltaT_ = dict.get<scalar>("deltaT");
        deltaTSave_ = deltaT_;
    }
    deltaT0_ = dict.get<scalar>("deltaT0");

    // Writes counted from the first run's start, while the interval is
    // the same
    if (dict.get<scalar>("writeInterval") == writeInterval_)
    {
        anchor_ = dict.get<scalar>("anchor");
        // As Time counts a step a write: within half a step of the time;
        // a start off the write times (a stop on a signal) counts the
        // writes before it
        writesBeforeStart_ = label
        (
            std::floor((value() - anchor_ + 0.5*deltaT_)/writeInterval_)
        );
    }
    Info<< "Restart state of time " << timeName() << " restored (t = "
        << value() << ", deltaT " << deltaT_ << ", writes counted from "
        << anchor_ << ")" << nl << endl;
}


void Foam::restartableTime::nameTheStepExactly()
{
    // As Time::operator++ does at its write times, which a stop on a signal
    // is not: a name that tells this step from its neighbours (within a
    // tenth of deltaT, or 10^-timePrecision)
    const scalar tol = max(min(pow(10.0, -precision_), 0.1*deltaT_), SMALL);
    const int oldPrecision = precision_;
    scalar named = 0;
    while
    (
        precision_ < maxPrecision_
     && readScalar(timeName(), named)
     && mag(named - timeToUserTime(value())) > tol
    )
    {
        ++precision_;
        setTime(value(), timeIndex());
    }
    if (precision_ != oldPrecision)
    {
        Info<< "Time precision raised from " << oldPrecision << " to "
            << precision_ << " to name time " << timeName() << endl;
    }
    if (precision_ == maxPrecision_)
    {
        WarningInFunction
            << "time " << timeName() << " is named at the largest precision, "
            << maxPrecision_ << ": its name may be a neighbouring step's"
            << endl;
    }
}


bool Foam::restartableTime::writeState() const
{
    const fileName dir(timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/"restartState");
    os.precision(17);
    os  << "// The exact time state, for a bitwise restart (restartableTime)"
        << nl
        << "name            \"" << timeName() << "\";" << nl
        << "value           " << value() << ';' << nl
        << "deltaT          " << deltaT_ << ';' << nl
        << "deltaT0         " << deltaT0_ << ';' << nl
        << "anchor          " << anchor_ << ';' << nl
        << "writeInterval   " << writeInterval_ << ';' << nl;
    return os.good();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::restartableTime::restartableTime
(
    const word& ctrlDictName,
    const argList& args
)
:
    Time(ctrlDictName, args),
    anchor_(startTime_),
    anchorInterval_(writeInterval_),
    writesBeforeStart_(0)
{
    findStartFolder();
    restoreState();
    catchSignals();
    if (writeFormat() == IOstream::ASCII && IOstream::defaultPrecision() < 17)
    {
        Info<< "Note: fields are written in ascii at writePrecision "
            << IOstream::defaultPrecision() << ": a restart continues to"
            << " that precision; binary, or writePrecision 17, restarts"
            << " bitwise" << nl << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::restartableTime::setDeltaT(const scalar deltaT, const bool adjust)
{
    followIntervalChange();
    Time::setDeltaT(deltaT, false);
    if (!adjust)
    {
        return;
    }
    if (writeControl_ == wcAdjustableRunTime)
    {
        // As Time::adjustDeltaT, with the writes counted from the anchor:
        // the same arithmetic in a run and in its restart
        const scalar timeToNextWrite = max
        (
            scalar(0),
            (writesBeforeStart_ + writeTimeIndex_ + 1)*writeInterval_
          - (value() - anchor_)
        );
        const scalar nSteps = timeToNextWrite/deltaT_;
        if (nSteps < labelMax)
        {
            const label n = max(label(1), label(std::round(nSteps)));
            const scalar newDeltaT = timeToNextWrite/n;
            // At most twice as long, at least a fifth as long (as Time)
            deltaT_ =
                newDeltaT >= deltaT_
              ? min(newDeltaT, 2*deltaT_)
              : max(newDeltaT, 0.2*deltaT_);
        }
    }
    functionObjects().adjustTimeStep();
}


void Foam::restartableTime::followIntervalChange()
{
    // Time rescales its count of writes from this run's start when the
    // controlDict's writeInterval changes in a run; the writes before the
    // start were counted in the old interval: count from this run's start
    if (writeInterval_ != anchorInterval_)
    {
        anchor_ = startTime_;
        writesBeforeStart_ = 0;
        anchorInterval_ = writeInterval_;
    }
}


Foam::Time& Foam::restartableTime::operator++()
{
    followIntervalChange();
    if (subCycling_ || writeControl_ != wcAdjustableRunTime)
    {
        return Time::operator++();
    }

    // Time decides an adjustableRunTime write from this run's start time:
    // from the anchor instead, where setDeltaT lands the steps, so that a
    // run restarted off its write times (after a stop on a signal) writes at
    // the first run's write times
    const scalar start = startTime_;
    startTime_ = anchor_;
    writeTimeIndex_ += writesBeforeStart_;
    Time::operator++();
    writeTimeIndex_ -= writesBeforeStart_;
    startTime_ = start;
    return *this;
}


bool Foam::restartableTime::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    // A signal on any rank stops every rank at this step, written
    label signal = stopSignal_;
    reduce(signal, maxOp<label>());
    if (signal)
    {
        restartableTime& self = const_cast<restartableTime&>(*this);
        self.nameTheStepExactly();
        Info<< nl << "Signal " << signal << " ("
            << (
                   signal == SIGINT ? "SIGINT"
                 : signal == SIGTERM ? "SIGTERM"
                 : signal == SIGUSR1 ? "SIGUSR1" : "?"
               )
            << "): writing time " << timeName() << " and stopping" << nl
            << endl;
        self.writeTime_ = true;
        stopAt(saWriteNow);
        endTime_ = value();
    }

    bool ok = Time::writeObject(fmt, ver, cmp, valid);
    if (ok && writeTime())
    {
        ok = writeState();
    }
    return ok;
}


// ************************************************************************* //
