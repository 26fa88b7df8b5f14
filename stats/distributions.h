// Distribution functions, written here so every platform gives the same numbers (formulas and
// sources at the top of distributions.cc). Conventions as in stats/statistics.h.
#pragma once

namespace foresight {

double NormalCdf(double z);
double NormalPdf(double z);
double NormalQuantile(double p);                 // Wichura, AS 241 (1988), |err| < 1e-15
double StudentTQuantile(double p, double dof);   // dof > 0
double ChiSquareQuantile(double p, double dof);  // dof > 0

}  // namespace foresight
