// SPDX-License-Identifier: LGPL-2.1-or-later
// 3D unit test of the local Coulomb law (paper eqs. (25)-(26)): for iterates in the open, stick
// and slip regimes, the analytical generalized Jacobian of the complementarity functions matches
// central finite differences (relative difference printed, must be small), the state is the
// expected one, and the semi-smooth Newton slip rows have a zero right-hand side at a consistent
// iterate (lambda_tau = F lambda_n a/|a|). The law's parameter scale is that of the paper (Pa, m).
#include <porofrac/mechanics/contact_law.h>
#include <porofrac/mechanics/contact_method.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace porofrac::mechanics;
using dealii::Tensor;

namespace
{
  const char *
  name(const FaceState s)
  {
    return s == FaceState::open ? "open" : (s == FaceState::stick ? "stick" : "slip");
  }

  void
  check(const char               *label,
        const LocalContactLaw<3> &law,
        const Tensor<1, 3>       &l,
        const Tensor<1, 3>       &j)
  {
    Tensor<2, 3> Jl, Jj;
    law.jacobian(l, j, Jl, Jj);
    double err = 0, ref = 0;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const double hl = 1e-6 * std::max(1.0, l.norm());
        const double hj = hl / law.c;
        Tensor<1, 3> lp = l, lm = l, jp = j, jm = j;
        lp[k] += hl;
        lm[k] -= hl;
        jp[k] += hj;
        jm[k] -= hj;
        const Tensor<1, 3> dl = (law.residual(lp, j) - law.residual(lm, j)) / (2 * hl);
        const Tensor<1, 3> dj = (law.residual(l, jp) - law.residual(l, jm)) / (2 * hj);
        for (unsigned int i = 0; i < 3; ++i)
          {
            err = std::max({err, std::abs(dl[i] - Jl[i][k]), std::abs(dj[i] - Jj[i][k]) / law.c});
            ref = std::max({ref, std::abs(Jl[i][k]), std::abs(Jj[i][k]) / law.c});
          }
      }
    std::cout << label << ": state " << name(law.state(l, j)) << ", Jacobian vs FD relative "
              << (err / ref < 1e-6 ? "< 1e-6" : "FAILED") << std::endl;
  }
} // namespace

int
main()
{
  const LocalContactLaw<3> law{0.6, 1e9};
  Tensor<1, 3>             l, j;
  // Open: b = lambda_n + c [u]_n < 0 (opening 1 mm), some old tangential multiplier.
  l[0] = 1e5;
  l[1] = 2e4;
  l[2] = -1e4;
  j[0] = -1e-3;
  j[1] = 2e-4;
  j[2] = 1e-4;
  check("open", law, l, j);
  // Stick: in contact, |a| < F b.
  l    = Tensor<1, 3>();
  j    = Tensor<1, 3>();
  l[0] = 1e7;
  l[1] = 1e6;
  l[2] = 2e6;
  j[0] = 1e-4;
  j[1] = 1e-4;
  j[2] = -2e-4;
  check("stick", law, l, j);
  // Slip: |a| > F b.
  j[1] = 8e-3;
  j[2] = -9e-3;
  check("slip", law, l, j);

  // Semi-smooth Newton rows at a consistent slip iterate: lambda_tau = F lambda_n a/|a|.
  l                   = Tensor<1, 3>();
  j                   = Tensor<1, 3>();
  l[0]                = 1e7;
  j[1]                = 3e-3;
  j[2]                = 4e-3;
  l[1]                = 0.6e7 * 0.6;
  l[2]                = 0.6e7 * 0.8;
  const auto      ssn = ContactMethodRegistry<3>::instance().create("semismooth newton", "test");
  const auto      as  = ContactMethodRegistry<3>::instance().create("active set", "test");
  LocalRows<3>    rows;
  const FaceState s  = ssn->rows(law, l, j, rows);
  const auto     &Al = rows.A_lambda, &Aj = rows.A_jump;
  const auto     &r = rows.rhs;
  std::cout << "consistent slip: state " << name(s) << ", |residual| / lambda_n "
            << (law.residual(l, j, true).norm() / l[0] < 1e-12 ? "< 1e-12" : "FAILED")
            << ", row rhs / lambda_n " << (r.norm() / l[0] < 1e-12 ? "< 1e-12" : "FAILED")
            << ", row residual "
            << ((Al * l + Aj * j - r).norm() / l[0] < 1e-9 ? "< 1e-9" : "FAILED") << std::endl;
  // Active-set rows at the same iterate are satisfied too.
  as->rows(law, l, j, rows);
  std::cout << "active set rows at the same iterate: "
            << ((Al * l + Aj * j - r).norm() / l[0] < 1e-9 ? "satisfied" : "FAILED") << std::endl;
  return 0;
}
