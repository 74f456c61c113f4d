// SPDX-License-Identifier: LGPL-2.1-or-later
// PoroFrac: global configuration and instantiation helpers.
#ifndef POROFRAC_BASE_CONFIG_H
#define POROFRAC_BASE_CONFIG_H

/// Expands INSTANTIATE(dim) for every space dimension PoroFrac supports.
#define POROFRAC_INSTANTIATE(INSTANTIATE) \
  INSTANTIATE(2)                          \
  INSTANTIATE(3)

namespace porofrac
{
  /// Version string printed by `porofrac --version` and written to summary.json.
  inline constexpr const char *version = "0.1.0";
} // namespace porofrac

#endif
