/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The time-step controller without a mesh (doc/theory.md [S18], [S19]):
    a failed attempt with the predictor is retried without it, then the
    step is cut back by cutBackFactor; after maxCutBacks failures in a row,
    or a step that would fall below minDeltaTRatio deltaT, the run stops;
    converged steps grow by timeStepGrowth up to deltaT; the state written
    for a restart gives the same next step; the predictor keyword's values
    ([S18c]: extrapolate, tangent, tangentFirst, none, and the former
    yes/no) and no predictor in a retry. Expected values follow from the
    rules by hand.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "timeStepController.H"
#include "IStringStream.H"

using namespace Foam;
using namespace unitTest;

int main()
{
    typedef timeStepController ctrl;

    Info<< "Retry, cut-back, growth (maxCutBacks 2, factor 0.5, growth 1.5)"
        << endl;
    {
        ctrl c(controls("maxCutBacks 2; cutBackFactor 0.5;"
                        " timeStepGrowth 1.5;"), 0.1);
        checkAbs("initial step is deltaT", c.deltaT(), 0.1, 0);
        checkTrue("first attempt uses the predictor", c.predict());

        checkTrue("failure with predictor -> RETRY", c.failed(0.1) == ctrl::RETRY);
        checkTrue("retry without predictor", !c.predict());
        checkTrue("retry fails -> CUT_BACK", c.failed(0.1) == ctrl::CUT_BACK);
        checkAbs("step halved", c.deltaT(), 0.05, 1e-15);
        checkTrue("new step uses the predictor again", c.predict());
        checkAbs("one failure counted", c.nFailures(), 1, 0);

        checkTrue("converged -> ACCEPT", c.converged() == ctrl::ACCEPT);
        checkAbs("failures reset", c.nFailures(), 0, 0);
        checkAbs("grown by 1.5", c.deltaT(), 0.075, 1e-15);
        c.converged();
        checkAbs("growth capped at deltaT", c.deltaT(), 0.1, 1e-15);

        // three failed attempts in a row: stop after maxCutBacks = 2
        c.failed(0.1);
        checkTrue("1st cut-back", c.failed(0.1) == ctrl::CUT_BACK);
        c.failed(0.05);
        checkTrue("2nd cut-back", c.failed(0.05) == ctrl::CUT_BACK);
        c.failed(0.025);
        checkTrue("3rd failure stops", c.failed(0.025) == ctrl::STOP);

        const string msg(c.stopMessage(2.5, 0.025, "no convergence", 2.4, false));
        checkTrue
        (
            "stop message names the last converged time",
            msg.find("The last converged time, 2.4, is written")
         != string::npos
        );
        checkTrue
        (
            "stop message counts the cut-backs",
            msg.find("after 2 cut-backs") != string::npos
        );
    }

    Info<< "Without predictor: a failure cuts back at once" << endl;
    {
        ctrl c(controls("predictor no;"), 1);
        checkTrue("no predictor", !c.predict());
        checkTrue("failure -> CUT_BACK", c.failed(1) == ctrl::CUT_BACK);
        checkAbs("default factor 0.5", c.deltaT(), 0.5, 0);
        c.converged();
        checkAbs("default growth 1.5", c.deltaT(), 0.75, 1e-15);
    }

    Info<< "The predictor's kinds ([S18], [S18c]): a retry uses none"
        << endl;
    {
        ctrl d(controls(""), 1);
        checkTrue
        (
            "default tangentFirst", d.predictor() == ctrl::TANGENT_FIRST
        );
        ctrl y(controls("predictor yes;"), 1);
        checkTrue("yes = extrapolate", y.predictor() == ctrl::EXTRAPOLATE);
        ctrl n(controls("predictor no;"), 1);
        checkTrue("no = none", n.predictor() == ctrl::NONE);
        ctrl z(controls("predictor none;"), 1);
        checkTrue("none", z.predictor() == ctrl::NONE && !z.predict());
        ctrl e(controls("predictor extrapolate;"), 1);
        checkTrue("extrapolate", e.predictor() == ctrl::EXTRAPOLATE);
        ctrl f(controls("predictor tangentFirst;"), 1);
        checkTrue("tangentFirst", f.predictor() == ctrl::TANGENT_FIRST);

        ctrl c(controls("predictor tangent;"), 1);
        checkTrue("tangent", c.predictor() == ctrl::TANGENT && c.predict());
        checkTrue("tangent fails -> RETRY", c.failed(1) == ctrl::RETRY);
        checkTrue("the retry without it", c.predictor() == ctrl::NONE);
        checkTrue("retry fails -> CUT_BACK", c.failed(1) == ctrl::CUT_BACK);
        checkTrue("the cut step with it", c.predictor() == ctrl::TANGENT);
    }

    Info<< "Minimum step: a cut below minDeltaTRatio deltaT stops" << endl;
    {
        ctrl c(controls("predictor no; minDeltaTRatio 0.3; maxCutBacks 10;"), 1);
        checkTrue("1 -> 0.5 allowed", c.failed(1) == ctrl::CUT_BACK);
        checkTrue("0.5 -> 0.25 < 0.3 stops", c.failed(0.5) == ctrl::STOP);
    }

    Info<< "Restart: the state gives the same next step" << endl;
    {
        ctrl a(controls("predictor no;"), 0.2);
        a.failed(0.2);
        a.failed(0.1);
        a.converged();
        ctrl b(controls("predictor no;"), 0.2);
        b.setState(a.state());
        checkAbs("same next step", b.deltaT(), a.deltaT(), 0);
        checkAbs("next step 0.075", b.deltaT(), 0.075, 1e-15);
        a.converged();
        b.converged();
        checkAbs("same step after growth", b.deltaT(), a.deltaT(), 0);

        // a deltaT changed in controlDict since the write: it is taken
        ctrl c(controls("predictor no;"), 0.01);
        checkTrue("changed deltaT reported", !c.setState(a.state()));
        checkAbs("the new deltaT is taken", c.deltaT(), 0.01, 0);
    }

    return exitCode();
}


// ************************************************************************* //
