// analysis/reportfit.cpp: the orders of convergence --report fits to its sweeps (report.h), and
// the check of each against its integrator's theoretical order.

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <sstream>

#include "analysis/reportstudy.h"
#include "analysis/stability.h"
#include "core/output.h"
#include "io/scenereader.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello {

double fittedOrder(const std::vector<ReportRow>& rows, Integrator integrator, double floor) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ReportRow& r : rows) {
    if (r.integrator != integrator || r.diverged || r.worldsOwn || !(r.rmsError > floor)) continue;
    double x = std::log(integrator == Integrator::RK45 ? r.tolerances.rtol : r.dt),
           y = std::log(r.rmsError);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (n < 2 || n * sxx - sx * sx == 0) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

OrderCheck checkOrder(const std::vector<ReportRow>& rows, Integrator integrator,
                      double referenceError, const ContactActivity& contacts) {
  OrderCheck check;
  check.integrator = integrator;
  check.theory = orderOf(integrator);
  check.referenceError = referenceError;
  const double floor = kFitFloor * referenceError;
  check.fitted = fittedOrder(rows, integrator, floor);
  if (sweepsTolerance(integrator) || std::isnan(check.fitted)) return check;
  check.far = std::fabs(check.fitted - check.theory) > kOrderSlack;
  if (!check.far) return check;
  check.contacts = contacts.inContact > 0;
  // The sweep's runs in the fit, and the largest of their steps.
  std::vector<ReportRow> fitted;
  for (const ReportRow& r : rows) {
    if (r.integrator != integrator || r.worldsOwn) continue;
    if (r.diverged)
      check.divergedSteps = true;
    else if (r.rmsError > floor)
      fitted.push_back(r);
  }
  // fittedOrder found two runs or more above the floor: `fitted` is not empty.
  check.finestError = fitted[0].rmsError;
  for (const ReportRow& r : fitted) check.finestError = std::min(check.finestError, r.rmsError);
  auto largest =
      std::max_element(fitted.begin(), fitted.end(),
                       [](const ReportRow& a, const ReportRow& b) { return a.dt < b.dt; });
  check.largestStep = largest->dt;
  fitted.erase(largest);
  check.withoutLargest = fittedOrder(fitted, integrator, floor);
  check.edgeOfStability = std::fabs(check.withoutLargest - check.theory) <= kOrderSlack;
  check.nearReference = check.finestError < kReferenceMargin * referenceError;
  return check;
}

}  // namespace jello
