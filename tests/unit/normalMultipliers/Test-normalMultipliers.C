/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The normal multipliers of a contact patch (normalMultipliers,
    doc/theory.md [C5b], [C5e], [C5f]) alone, on three faces, against
    values worked out by hand:
      - settings: the predicted pressure by default, the plain penalty with
        'pressurePrediction no', the augmented Lagrangian with its
        tolerance; both asked for: a FatalIOError naming the keywords;
      - [C5f] prediction: pressures 10, 5, 0 then 20, 2, 0 committed;
        with the step-size ratio 0.5 the start is 25, 0.5, 0 (linear in
        time), with 2 it is 40, 0 (a pressure is never negative), 0; with
        0 (no extrapolation) the last pressures; a face out of reach
        commits 0; the plain penalty commits nothing;
      - [C5b], [C5e] Uzawa's updates with KN = 1: from 0 to 1 (the first
        update plain), then a change of 0.5 after one of 1 (rho = 0.5) is
        extrapolated to 2, the limit of 1 + 0.5 + 0.25 + ...; a change
        below the tolerance ends the updates (false, nothing changed), as
        does maxIterations; a new attempt starts from the step's start;
      - restart: the entries written read back give the same prediction.
    Tolerance 1e-12 absolute (round-off on numbers of order 1-40).

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "dictionaryTestTools.H"
#include "normalMultipliers.H"
#include "OStringStream.H"

using namespace Foam;

int main()
{
    FatalIOError.throwExceptions();
    FatalError.throwExceptions();
    const scalar tol = 1e-12;

    Info<< "settings" << endl;
    {
        normalMultipliers m;
        m.readSettings(unitTest::dictOf(""), 0.01);
        unitTest::checkTrue("default: predicted", m.predicted());
        unitTest::checkTrue("default: shifted, not augmented",
            m.shifted() && !m.augmented());

        normalMultipliers plain;
        plain.readSettings(unitTest::dictOf("pressurePrediction no;"), 0.01);
        unitTest::checkTrue("pressurePrediction no: the plain penalty",
            !plain.shifted());

        normalMultipliers a;
        a.readSettings
        (
            unitTest::dictOf("augmentedLagrangian { tolerance 1e-6; }"), 0.01
        );
        unitTest::checkTrue("augmentedLagrangian: augmented, not predicted",
            a.augmented() && !a.predicted() && a.shifted());

        const std::string msg = unitTest::fatalMessage([]
        {
            normalMultipliers both;
            both.readSettings
            (
                unitTest::dictOf
                (
                    "augmentedLagrangian yes; pressurePrediction yes;"
                ),
                0.01
            );
        });
        unitTest::checkTrue("both: an error naming both keywords",
            msg.find("augmentedLagrangian") != std::string::npos
         && msg.find("pressurePrediction") != std::string::npos);
    }

    Info<< "[C5f] prediction" << endl;
    {
        normalMultipliers m;
        m.readSettings(unitTest::dictOf(""), 0.01);
        m.resize(3);
        const scalar p1[3] = {10, 5, 0};
        const scalar p2[3] = {20, 2, 0};
        for (label i = 0; i < 3; ++i) { m.commit(i, p1[i]); }
        for (label i = 0; i < 3; ++i) { m.commit(i, p2[i]); }

        m.predict(0.5);
        unitTest::checkAbs("ratio 0.5: face 0", m[0], 25, tol);
        unitTest::checkAbs("ratio 0.5: face 1", m[1], 0.5, tol);
        unitTest::checkAbs("ratio 0.5: face 2", m[2], 0, tol);
        m.predict(2);
        unitTest::checkAbs("ratio 2: face 0", m[0], 40, tol);
        unitTest::checkAbs("ratio 2: face 1 never negative", m[1], 0, tol);
        m.predict(0);
        unitTest::checkAbs("no extrapolation: the last pressure", m[0], 20, tol);
        unitTest::checkAbs("committed", m.committed(1), 2, tol);

        // restart: what is written, read back
        OStringStream os;
        m.write(os);
        normalMultipliers r;
        const dictionary d(unitTest::dictOf(os.str()));
        r.readSettings(d, 0.01);
        r.resize(3);
        r.readState(d, 3);
        m.predict(0.5);
        r.predict(0.5);
        unitTest::checkAbs("restart: the same prediction, face 0", r[0], m[0], tol);
        unitTest::checkAbs("restart: the same prediction, face 1", r[1], m[1], tol);

        m.commitOpen(0);
        m.predict(1);
        unitTest::checkAbs("a face out of reach: 0, whatever came before", m[0], 0, tol);

        normalMultipliers plain;
        plain.readSettings(unitTest::dictOf("pressurePrediction no;"), 0.01);
        plain.resize(1);
        plain.commit(0, 7);
        plain.predict(1);
        unitTest::checkAbs("plain penalty: no multiplier", plain[0], 0, tol);
    }

    Info<< "[C5b], [C5e] Uzawa's updates" << endl;
    {
        normalMultipliers m;
        m.readSettings
        (
            unitTest::dictOf("augmentedLagrangian { tolerance 1e-3; }"), 0.01
        );
        m.resize(1);
        m.predict(0);
        const scalar KN = 1;
        unitTest::checkTrue("first update",
            m.update(scalarField(1, 1.0), KN, 0, "testPatch"));
        unitTest::checkAbs("first update plain: 1", m[0], 1, tol);
        unitTest::checkTrue("second update",
            m.update(scalarField(1, 1.5), KN, 0, "testPatch"));
        unitTest::checkAbs("rho 0.5 extrapolated to the limit 2", m[0], 2, tol);
        unitTest::checkTrue("a change below the tolerance: no update",
            !m.update(scalarField(1, 2.0005), KN, 0, "testPatch"));
        unitTest::checkAbs("nothing changed", m[0], 2, tol);
        m.reset();
        unitTest::checkAbs("a new attempt: the step's start", m[0], 0, tol);

        normalMultipliers one;
        one.readSettings
        (
            unitTest::dictOf
            (
                "augmentedLagrangian { tolerance 1e-3; maxIterations 1; }"
            ),
            0.01
        );
        one.resize(1);
        one.predict(0);
        one.update(scalarField(1, 1.0), KN, 0, "testPatch");
        unitTest::checkTrue("maxIterations 1: no second update",
            !one.update(scalarField(1, 5.0), KN, 0, "testPatch"));
        unitTest::checkAbs("maxIterations 1: the first update kept", one[0], 1, tol);
    }

    return unitTest::exitCode();
}


// ************************************************************************* //
