#pragma once
/// @file
/// A SUNDIALS nonlinear solver for IDA's corrector: Newton's method that, when the iteration
/// stalls or diverges with an iteration matrix from an earlier point, re-evaluates the matrix
/// at the current iterate and goes on from there.
///
/// IDA's own Newton solver (SUNNonlinSol_Newton) keeps one iteration matrix for many steps
/// (modified Newton). On a failure with an old matrix it evaluates a new one at the predictor
/// and starts over from the predictor; a second failure cuts the step to a quarter. That is
/// right for smooth problems. For a problem whose Jacobian changes abruptly within a step
/// (a film node that switches between pressure and fill fraction: libemb/tribology, the
/// smoothed JFO switch), the matrix at the predictor is on the wrong branch again, and every
/// such switch costs failures and a shrunken step. Evaluating the matrix at the current
/// iterate instead is Newton's method proper, and converges where the iterate is.
///
/// The convergence test stays IDA's (rate estimate and tolerance); after a refresh the test
/// restarts at iteration 0, as after any new matrix. At most `max_refreshes` refreshes per
/// corrector solve; the iterations per matrix stay IDA's limit (maxcor, 4).

#include <sundials/sundials_nonlinearsolver.h>

namespace emb {

/// @param max_refreshes >= 1. The solver owns a work vector cloned from `like`; free it with
///   SUNNonlinSolFree after IDAFree.
SUNNonlinearSolver MakeRefreshingNewton(N_Vector like, SUNContext ctx, int max_refreshes);

}  // namespace emb
