/*---------------------------------------------------------------------------*\
License
    This file is part of triboFoam.

    triboFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by the
    Free Software Foundation, either version 3 of the License, or (at your
    option) any later version. See <https://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

Description
    The extension points of doc/architecture.md ("Where a new piece goes"),
    each shown by one new class written here, outside the libraries,
    registered in its run-time selection table and selected by 'type'
    through the same New() the solver calls; nothing else changes:
      - friction law 'constantShear' (a friction stress tau0 independent
        of the pressure, the radial return of the built-in laws): sticks
        below tau0, slides at exactly tau0 at any pressure; its tangent
        against central differences (1e-6, as the built-in laws' [F7]);
        an unknown keyword refused;
      - mechanical law 'saintVenantKirchhoff' (P = F S, S = lambda tr(E) I
        + 2 mu E) with the base class's difference tangent: stress-free at
        F = I; the linear elastic law's stress in the small-strain limit
        (1e-5); the analytic uniaxial stretch (1e-12); objective,
        P(Q F) = Q P(F) (1e-12);
      - rigid obstacle 'sphere' (the outside of a sphere): the gap of
        points inside and outside, the normal, and the derivatives of the
        nearest point and of the normal against central differences
        (1e-6), moved by the base class's translation;
      - linear solver 'biCGStabJacobi' (Eigen's BiCGSTAB with a diagonal
        preconditioner, an iterative solver): the 2-D elastic block
        operator of the linear-solver tests solved to the requested
        tolerance, against eigenLU.

\*---------------------------------------------------------------------------*/

#include "unitTest.H"
#include "frictionTestTools.H"
#include "mechanicalLawTestTools.H"
#include "rigidObstacle.H"
#include "solverRuns.H"
#include "strictDictionary.H"
#include "addToRunTimeSelectionTable.H"
#include <Eigen/IterativeLinearSolvers>

using namespace Foam;

// * * * * * * * * * * * * * * * The new classes * * * * * * * * * * * * * * //

namespace Foam
{
namespace extensionExamples
{

//- A friction stress tau0 whatever the pressure (Tresca's friction)
class constantShear
:
    public frictionLaw
{
    scalar tau0_;

public:

    TypeName("constantShear");

    explicit constantShear(const dictionary& dict)
    :
        frictionLaw(dict),
        tau0_(dict.get<scalar>("tau0"))
    {
        checkKeywords(dict, {"tau0"});
    }

    virtual void update
    (
        const frictionState& old,
        const frictionInput& in,
        frictionResult& out
    ) const
    {
        if (!normalContact(in, out))
        {
            openContact(old, in, out);
            return;
        }
        out.state = old;
        out.state.slipRate = 0;
        const tensor P = projector(in.n);
        const vector xiTrial = KT_*(P & (in.gT - old.plasticSlip));
        const scalar tau0 = tau0_;
        auto threshold = [=](scalar, slipThreshold& thr)
        {
            thr.Y = tau0;
            thr.dYdDg = 0;
            thr.dYdgN = 0;
            thr.dYdgT = Zero;
        };
        radialReturn::output rr;
        radialReturn::solve(xiTrial, Zero, KT_, KT_, P, threshold, rr);
        setFromReturn(old, in, rr, out);
    }
};

defineTypeNameAndDebug(constantShear, 0);
addToRunTimeSelectionTable(frictionLaw, constantShear, dictionary);


//- Saint Venant-Kirchhoff hyperelasticity: P = F S(E), E = (F^T F - I)/2
class saintVenantKirchhoff
:
    public mechanicalLaw
{
public:

    TypeName("saintVenantKirchhoff");

    explicit saintVenantKirchhoff(const dictionary& dict)
    :
        mechanicalLaw(dict)
    {
        checkKeywords(dict, wordList());
    }

    virtual tensor stress
    (
        const tensor& F,
        const materialState& old,
        materialState& updated
    ) const
    {
        const symmTensor E(0.5*(symm(F.T() & F) - symmTensor::I));
        const symmTensor S(lambda()*tr(E)*symmTensor::I + 2*mu()*E);
        updated = old;
        return F & S;
    }
};

defineTypeNameAndDebug(saintVenantKirchhoff, 0);
addToRunTimeSelectionTable(mechanicalLaw, saintVenantKirchhoff, dictionary);


//- The outside of a sphere (the free side): centre and radius
class sphere
:
    public rigidObstacle
{
    point centre_;
    scalar radius_;

protected:

    virtual bool nearestInitial
    (
        const point& x0,
        const scalar maxDistance,
        obstaclePoint& cp,
        const label
    ) const
    {
        const vector r = x0 - centre_;
        const scalar d = mag(r);
        if (d < VSMALL || mag(d - radius_) > maxDistance)
        {
            return false;
        }
        const vector n = r/d;
        const tensor tangential = tensor::I - sqr(n);
        cp.n = n;
        cp.p = centre_ + radius_*n;
        cp.gap = d - radius_;
        cp.hint = -1;
        cp.dndx = tangential/d;
        cp.dpdx = radius_*cp.dndx;
        return true;
    }

public:

    TypeName("sphere");

    sphere(const dictionary& dict, const fileName&)
    :
        rigidObstacle(dict),
        centre_(dict.get<point>("centre")),
        radius_(readPositive(dict, "radius"))
    {
        checkKeywords(dict, wordList({"centre", "radius"}));
    }
};

defineTypeNameAndDebug(sphere, 0);
addToRunTimeSelectionTable(rigidObstacle, sphere, dictionary);


//- BiCGSTAB preconditioned by the diagonal (Eigen): an iterative solver
class biCGStabJacobi
:
    public linearSolver
{
    Eigen::SparseMatrix<double> A_;
    Eigen::BiCGSTAB
    <
        Eigen::SparseMatrix<double>, Eigen::DiagonalPreconditioner<double>
    > solver_;
    label maxIterations_;

public:

    TypeName("biCGStabJacobi");

    biCGStabJacobi(const dictionary& dict, const blockSparseMatrix& matrix)
    :
        linearSolver(dict, matrix),
        maxIterations_(dict.getOrDefault<label>("maxIterations", 10000))
    {
        strictDictionary::check
        (
            dict, {"type", "maxIterations"}, "linear solver biCGStabJacobi"
        );
    }

    virtual string description() const
    {
        return "BiCGSTAB, diagonal preconditioner (Eigen)";
    }

    virtual bool inexact() const
    {
        return true;
    }

    virtual bool update()
    {
        A_ = matrix_.eigenMatrix();
        solver_.setMaxIterations(maxIterations_);
        solver_.compute(A_);
        return solver_.info() == Eigen::Success;
    }

    virtual performance solve
    (
        const Eigen::VectorXd& b,
        Eigen::VectorXd& x,
        const scalar relTol
    )
    {
        solver_.setTolerance(relTol);
        x = solver_.solveWithGuess(b, x);
        performance p;
        p.iterations = solver_.iterations();
        p.relativeResidual = (b - A_*x).norm()/max(b.norm(), VSMALL);
        p.converged = p.relativeResidual <= relTol && x.allFinite();
        if (!p.converged)
        {
            p.reason = "BiCGSTAB stopped at " + Foam::name(p.relativeResidual);
        }
        return p;
    }
};

defineTypeNameAndDebug(biCGStabJacobi, 0);
addToRunTimeSelectionTable(linearSolver, biCGStabJacobi, dictionary);

} // End namespace extensionExamples
} // End namespace Foam


// * * * * * * * * * * * * * * * * * Checks  * * * * * * * * * * * * * * * * //

namespace
{

template<class Error>
bool throwsNaming(const std::function<void()>& f, const std::string& word)
{
    try
    {
        f();
    }
    catch (const Error& e)
    {
        return std::string(e.message()).find(word) != std::string::npos;
    }
    return false;
}


void frictionLawChecks()
{
    Info<< "friction law constantShear" << endl;
    const scalar KN = 1e13, tau0 = 5e7;
    autoPtr<frictionLaw> law = frictionTest::law
    (
        "type constantShear; KN 1e13; KT 1e13; tau0 5e7;"
    );
    unitTest::checkTrue("selected by type", law->type() == "constantShear");
    const frictionState old = law->initialState();
    for (const scalar tN : {1e6, 1e8, 1e10})
    {
        frictionInput in;
        in.n = vector(0, 0, 1);
        in.gN = tN/KN;
        in.dt = 1;
        frictionResult r;
        in.gT = vector(1e-6, 0, 0);             // KT gT = 1e7 < tau0
        law->update(old, in, r);
        unitTest::checkRel
        (
            "tN " + std::string(Foam::name(tN)) + ": sticks below tau0",
            mag(r.tT), 1e7, 1e-12
        );
        in.gT = vector(3e-5, 4e-5, 0);          // far beyond
        law->update(old, in, r);
        unitTest::checkRel
        (
            "tN " + std::string(Foam::name(tN)) + ": slides at tau0",
            mag(r.tT), tau0, 1e-12
        );
        unitTest::checkBelow
        (
            "tN " + std::string(Foam::name(tN))
          + ": tangent against differences",
            frictionTest::tangentError(*law, old, in), 1e-6
        );
    }
    unitTest::checkTrue
    (
        "unknown keyword refused",
        throwsNaming<IOerror>
        (
            [] { frictionTest::law("type constantShear; KN 1; KT 1; tau0 1; "
                                   "tauO 2;"); },
            "tauO"
        )
    );
}


void mechanicalLawChecks()
{
    Info<< "mechanical law saintVenantKirchhoff" << endl;
    const std::string steel = "rho 7900; E 2e11; nu 0.3;";
    autoPtr<mechanicalLaw> svk =
        mechanicalLawTest::law("type saintVenantKirchhoff; " + steel);
    autoPtr<mechanicalLaw> hooke =
        mechanicalLawTest::law("type linearElastic; " + steel);
    const materialState old;
    materialState s;

    unitTest::checkBelow
    (
        "stress-free at F = I",
        mag(svk->stress(tensor::I, old, s)), 1e-6
    );

    const tensor H(1, 2, -1, 0.5, -3, 1, 2, 1, 1.5);
    const tensor Fsmall(tensor::I + 1e-6*H);
    const tensor Ph = hooke->stress(Fsmall, old, s);
    unitTest::checkBelow
    (
        "small strain: the linear elastic stress",
        mag(svk->stress(Fsmall, old, s) - Ph)/mag(Ph), 1e-5
    );

    // Uniaxial stretch l: E11 = (l^2 - 1)/2, S11 = (lambda + 2 mu) E11,
    // P11 = l S11
    const scalar l = 1.2;
    const scalar E11 = 0.5*(l*l - 1);
    const scalar P11 = l*(svk->lambda() + 2*svk->mu())*E11;
    const tensor F(l, 0, 0, 0, 1, 0, 0, 0, 1);
    unitTest::checkRel
    (
        "uniaxial stretch 1.2: P11", svk->stress(F, old, s).xx(), P11, 1e-12
    );

    const scalar a = 0.7;
    const tensor Q
    (
        std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1
    );
    const tensor Fg(tensor::I + 0.1*H);
    const tensor P = svk->stress(Fg, old, s);
    unitTest::checkBelow
    (
        "objective: P(Q F) = Q P(F)",
        mag(svk->stress(Q & Fg, old, s) - (Q & P))/mag(P), 1e-12
    );

    stressTangent dPdF;
    const tensor Pt = svk->stressAndTangent(Fg, old, s, dPdF);
    unitTest::checkBelow
    (
        "the base class's tangent: the same stress",
        mag(Pt - P)/mag(P), 1e-14
    );
}


void obstacleChecks()
{
    Info<< "rigid obstacle sphere" << endl;
    IStringStream is
    (
        "type sphere; centre (1 2 3); radius 0.5;"
        " translation constant (0 0 0.1);"
    );
    const dictionary d(is);
    autoPtr<rigidObstacle> s = rigidObstacle::New(d, ".");
    unitTest::checkTrue("selected by type", s->type() == "sphere");

    const point c(1, 2, 3.1);                   // moved by the translation
    const vector dir = vector(1, -2, 2)/3;
    for (const scalar r : {0.8, 0.45})
    {
        const point x = c + r*dir;
        obstaclePoint cp;
        const std::string tag = "|x - c| = " + std::string(Foam::name(r));
        unitTest::checkTrue(tag + ": found", s->nearest(x, 0, 1, cp));
        unitTest::checkRel(tag + ": gap", cp.gap, r - 0.5, 1e-12);
        unitTest::checkBelow(tag + ": normal", mag(cp.n - dir), 1e-12);

        const scalar h = 1e-6;
        scalar errN = 0, errP = 0;
        for (direction k = 0; k < 3; ++k)
        {
            vector e(Zero);
            e[k] = h;
            obstaclePoint cpP, cpM;
            s->nearest(x + e, 0, 1, cpP);
            s->nearest(x - e, 0, 1, cpM);
            const vector col(cp.dndx.x()[k], cp.dndx.y()[k], cp.dndx.z()[k]);
            const vector colP
            (
                cp.dpdx.x()[k], cp.dpdx.y()[k], cp.dpdx.z()[k]
            );
            errN = max(errN, mag((cpP.n - cpM.n)/(2*h) - col));
            errP = max(errP, mag((cpP.p - cpM.p)/(2*h) - colP));
        }
        unitTest::checkBelow(tag + ": dn/dx against differences", errN, 1e-6);
        unitTest::checkBelow(tag + ": dp/dx against differences", errP, 1e-6);
    }
    obstaclePoint far;
    unitTest::checkTrue
    (
        "beyond maxDistance: not found", !s->nearest(c + 2*dir, 0, 1, far)
    );
}


void linearSolverChecks()
{
    Info<< "linear solver biCGStabJacobi" << endl;
    autoPtr<blockSparseMatrix> M =
        eo::build(eo::grid{12, 12, 1, 0.01}, 2e11, 0.3);
    const outcome lu = solveWith("type eigenLU;", M());
    const outcome it = solveWith("type biCGStabJacobi;", M());
    unitTest::checkTrue("selected by type: converged", it.p.converged);
    unitTest::checkTrue("iterative: iterations > 0", it.p.iterations > 0);
    unitTest::checkBelow
    (
        "|b - M x|/|b| at the requested tolerance", it.p.relativeResidual,
        1e-10
    );
    unitTest::checkBelow
    (
        "against eigenLU", maxError(it.x, lu.x), 1e-6
    );
}

} // End namespace


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    frictionLawChecks();
    mechanicalLawChecks();
    obstacleChecks();
    linearSolverChecks();

    return unitTest::exitCode();
}

// ************************************************************************* //
