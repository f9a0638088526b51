/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    Identification of the relaxation law from stick-slip onsets
    (doc/theory.md [F32]), by round trip: the paper-board relaxation law
    ([F27]: gamma = 0.723, t** = 2.729 s, a = 0.0349, b = 0.0489,
    mu* = 0.369, V* = 1 um/s, sigma = 1e4 Pa) gives, through
    slidingStability ([F31]), the table (V, mu_ss, k_c, omega_c) at 10
    velocities from 0.1 to 100 um/s, without and with a block mass
    (1e6 kg/m^2: M omega_c^2 is 5 to 75 % of k_c above 10 um/s);
    relaxationIdentification reads the law back:
      - exact table: gamma, t**, a, b, mu* within 0.5 % (achieved ~1e-6);
      - 2 % Gaussian noise on k_c (50 tables, fixed seed): gamma and t**
        within 5 % in every table, and the 95 % intervals cover the truth
        in at least 85 % of them;
      - the law dictionary written is a law that gives the table back;
      - bad tables: non-increasing V, k_c <= 0, fewer than 3 rows: errors
        naming the keyword and the file.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "slidingStability.H"
#include "relaxationIdentification.H"
#include "OStringStream.H"
#include <random>

using namespace Foam;

namespace
{

const scalar sigma = 1e4, VStar = 1e-6, gammaT = 0.723, tStarT = 2.729;
const scalar aT = 0.0349, bT = 0.0489, muT = 0.369;

const std::string paperBoard =
    "type rateState; stateLaw relaxation; KN 1e12; KT 1e13;"
    " muStar 0.369; a 0.0349; b 0.0489; VStar 1e-6;"
    " relaxationTime 2.729; gamma 0.723; creepVelocity 1e-15;";

struct table
{
    scalarList V, Fss, kc, omegac;
};

table generate(const frictionLaw& law, const scalar M)
{
    const slidingStability stab(law, sigma);
    table t;
    const label n = 10;
    t.V.setSize(n);
    t.Fss.setSize(n);
    t.kc.setSize(n);
    t.omegac.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        t.V[i] = 1e-7*std::pow(1e3, scalar(i)/(n - 1));
        const slidingStability::critical c = stab.criticalStiffness(t.V[i], M);
        t.Fss[i] = c.lin.Fss;
        t.kc[i] = c.kc;
        t.omegac[i] = c.omegac;
    }
    return t;
}

relaxationIdentification identify(const table& t, const scalar M)
{
    return relaxationIdentification
    (
        t.V, t.Fss, t.kc, t.omegac, M, sigma, VStar, 0.95, false,
        dictionary::null, "table", "generated"
    );
}

bool inside(const relaxationIdentification::estimate& e, const scalar v)
{
    return e.interval.first() <= v && v <= e.interval.second();
}

} // End anonymous namespace


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    autoPtr<frictionLaw> law = frictionTest::law(paperBoard);

    for (const scalar M : {scalar(0), scalar(1e6)})
    {
        Info<< "Round trip, block mass " << M << " kg/m^2" << endl;
        const table t = generate(*law, M);
        const relaxationIdentification id = identify(t, M);
        const std::string m = M > 0 ? " (mass)" : "";
        Info<< "    relative errors: gamma " << id.gamma().value/gammaT - 1
            << ", t** " << id.tStar().value/tStarT - 1 << ", a "
            << id.aEstimate().value/aT - 1 << ", b "
            << id.bEstimate().value/bT - 1 << ", mu* "
            << id.muStar().value/muT - 1 << endl;
        unitTest::checkRel("gamma" + m, id.gamma().value, gammaT, 5e-3);
        unitTest::checkRel("t**" + m, id.tStar().value, tStarT, 5e-3);
        unitTest::checkRel("a" + m, id.aEstimate().value, aT, 5e-3);
        unitTest::checkRel("b" + m, id.bEstimate().value, bT, 5e-3);
        unitTest::checkRel("mu*" + m, id.muStar().value, muT, 5e-3);
        unitTest::checkBelow
        (
            "t** phi_ss: rms of log10 about the power law" + m,
            id.tauFit().rms, 1e-7
        );
        unitTest::checkRel
        (
            "L_a(V*) = V* t**" + m,
            id.La()[0]/std::pow(t.V[0]/VStar, 1 - gammaT), VStar*tStarT, 5e-3
        );

        // The written law gives the table back
        OStringStream os;
        os.precision(10);
        id.writeLaw(os);
        autoPtr<frictionLaw> back =
            frictionTest::law(os.str() + " KN 1e12; KT 1e13;");
        const table t2 = generate(*back, M);
        scalar err = 0;
        forAll(t.V, i)
        {
            err = max(err, mag(t2.kc[i] - t.kc[i])/t.kc[i]);
            err = max(err, mag(t2.omegac[i] - t.omegac[i])/t.omegac[i]);
            err = max(err, mag(t2.Fss[i] - t.Fss[i])/t.Fss[i]);
        }
        unitTest::checkBelow
        (
            "the written law's k_c, omega_c, F_ss = the table's (max rel)" + m,
            err, 1e-4
        );
    }

    Info<< "2 % noise on k_c, 50 tables" << endl;
    {
        const table t0 = generate(*law, 0);
        std::mt19937 gen(20261123);
        std::normal_distribution<double> noise(0, 0.02);
        scalar worstGamma = 0, worstT = 0, widest = 0;
        label coverG = 0, coverT = 0;
        const label n = 50;
        for (label r = 0; r < n; ++r)
        {
            table t = t0;
            forAll(t.kc, i) t.kc[i] *= 1 + noise(gen);
            const relaxationIdentification id = identify(t, 0);
            worstGamma = max(worstGamma, mag(id.gamma().value/gammaT - 1));
            worstT = max(worstT, mag(id.tStar().value/tStarT - 1));
            widest = max
            (
                widest,
                (id.gamma().interval.second() - id.gamma().interval.first())
               /(2*gammaT)
            );
            coverG += inside(id.gamma(), gammaT);
            coverT += inside(id.tStar(), tStarT);
        }
        Info<< "    worst gamma error " << worstGamma << ", t** " << worstT
            << "; widest 95 % interval of gamma +-" << widest << " (rel);"
            << " coverage gamma " << coverG << "/" << n << ", t** " << coverT
            << "/" << n << endl;
        unitTest::checkBelow("gamma within 5 % in every table", worstGamma, 0.05);
        unitTest::checkBelow("t** within 5 % in every table", worstT, 0.05);
        unitTest::checkTrue
        (
            "95 % intervals cover gamma in >= 85 % of the tables",
            coverG >= 0.85*n
        );
        unitTest::checkTrue
        (
            "95 % intervals cover t** in >= 85 % of the tables",
            coverT >= 0.85*n
        );
    }

    Info<< "Bad tables" << endl;
    {
        const table t0 = generate(*law, 0);
        auto rejects = [&](table t, const std::string& word)
        {
            try
            {
                identify(t, 0);
            }
            catch (const Foam::IOerror& e)
            {
                const std::string m(e.message());
                return
                    m.find(word) != std::string::npos
                 && m.find("'table'") != std::string::npos
                 && m.find("generated") != std::string::npos;
            }
            return false;
        };
        table t = t0;
        std::swap(t.V[3], t.V[4]);
        unitTest::checkTrue
        (
            "non-increasing V: error names keyword, file, 'increasing'",
            rejects(t, "increasing")
        );
        t = t0;
        t.kc[2] = -t.kc[2];
        unitTest::checkTrue
        (
            "negative k_c: error names keyword, file, 'k_c'",
            rejects(t, "k_c")
        );
        t = t0;
        for (List<scalar>* l : {&t.V, &t.Fss, &t.kc, &t.omegac})
        {
            l->setSize(2);
        }
        unitTest::checkTrue
        (
            "2 rows for 2 parameters: error names keyword, file, 'rows'",
            rejects(t, "rows")
        );
    }

    return unitTest::exitCode();
}


// ************************************************************************* //
