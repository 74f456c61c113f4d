// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_RANDOM_DISCS_H
#define POROFRAC_GEOMETRY_RANDOM_DISCS_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/geometry/polygon_network.h>

#include <map>
#include <string>

namespace porofrac
{
  namespace geometry
  {
    /**
     * The deck's "Geometry/Random discs" subsection: a seeded generator of disc fractures for 3D
     * networks (count, radii, orientations, centres, sides). The random numbers come from
     * std::mt19937_64 through our own transformations, so that a seed gives the same network
     * with every compiler and standard library.
     */
    struct RandomDiscParameters
    {
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      unsigned int count      = 0;
      unsigned int seed       = 1;
      unsigned int first_id   = 1;
      double       radius_min = 0.1, radius_max = 0.3; ///< m
      std::string  radius_distribution  = "uniform";   ///< uniform | power law
      double       power_law_exponent   = 2.5;         ///< density of r proportional to r^-a
      std::string  orientation          = "uniform";   ///< uniform | fisher
      std::string  mean_normal          = "(0, 0, 1)"; ///< fisher: mean pole
      double       fisher_concentration = 10;          ///< fisher: kappa
      unsigned int sides                = 12;
      std::string  centre_region;              ///< "(x0, y0, z0) (x1, y1, z1)"; empty: the box
      double       minimum_feature_size = 0;   ///< m; 0: reject only invalid discs
      double       minimum_angle        = 0;   ///< degrees; with h > 0 (fractures, faces)
      unsigned int max_attempts         = 100; ///< per disc
    };

    /// What the generator did: discs accepted, candidates rejected by reason.
    struct RandomDiscStatistics
    {
      unsigned int                        accepted = 0;
      std::map<std::string, unsigned int> rejected;
    };

    /**
     * Appends @p parameters.count discs to @p network (whose own fractures are validated). A
     * candidate is redrawn, and counted by reason, when it would be invalid input (outside the
     * box, or in one plane with a fracture it overlaps) and, with a positive minimum feature size
     * h, when it would make a feature smaller than h that the mesh would have to resolve: it
     * comes closer than h to a fracture or a face of the box without meeting it, has a
     * corner closer than h to one (or a fracture has a corner closer than h to it) without
     * touching it, meets one in a
     * segment shorter than h, or its intersection segments come closer than h to others on the
     * same fracture without meeting them; and, with a minimum angle, when it meets a fracture or
     * cuts the boundary at a smaller angle.
     */
    RandomDiscStatistics
    add_random_discs(const RandomDiscParameters &parameters, PolygonNetwork &network);
  } // namespace geometry
} // namespace porofrac

#endif
