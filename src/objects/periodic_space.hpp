// The fluid's periodic axes as the object engine meets them. An object is never cut at a
// periodic face: its particles stay together, and the whole object is moved by a period once its
// centre has left the domain (ObjectWorld::step). So two objects may lie a period apart, and a
// pair's separation is taken to its nearest image; a search for what a particle touches runs from
// each image of its position that lies within reach of the domain.
#pragma once

#include <cmath>

#include "objects/math3d.hpp"

namespace sph::objects {

struct PeriodicSpace {
  bool periodic[3] = {false, false, false};
  DVec3 lo;      // the domain's lower faces
  DVec3 length;  // the period along each periodic axis; 0 along the others

  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }

  // d − L round(d / L) along each periodic axis: the shortest of d's images, however many
  // periods apart the two positions lie.
  DVec3 nearest(DVec3 d) const {
    if (periodic[0]) d.x -= length.x * std::round(d.x / length.x);
    if (periodic[1]) d.y -= length.y * std::round(d.y / length.y);
    if (periodic[2]) d.z -= length.z * std::round(d.z / length.z);
    return d;
  }

  // x moved by whole periods into [lo, lo + L) along each periodic axis.
  DVec3 wrapped(DVec3 x) const {
    const auto wrap = [](double v, double lo, double length) {
      const double w = v - length * std::floor((v - lo) / length);
      return w < lo + length ? w : lo;  // rounding can land a hair past the upper face
    };
    if (periodic[0]) x.x = wrap(x.x, lo.x, length.x);
    if (periodic[1]) x.y = wrap(x.y, lo.y, length.y);
    if (periodic[2]) x.z = wrap(x.z, lo.z, length.z);
    return x;
  }

  // The shift by whole periods that brings the point c back inside [lo, lo + L): what moves an
  // object whose centre is c.
  DVec3 shiftInto(DVec3 c) const { return wrapped(c) - c; }

  // Calls visit(shift) for the zero shift and for each shift by a period (along one axis or,
  // near an edge or a corner, several) that brings a wrapped position x within `reach` of the
  // domain from beyond the opposite face: the images to search from. The period must exceed
  // twice the reach, so that each axis has at most one.
  template <class Visit>
  void forEachImage(DVec3 x, double reach, Visit&& visit) const {
    const double at[3] = {x.x, x.y, x.z}, los[3] = {lo.x, lo.y, lo.z};
    const double lengths[3] = {length.x, length.y, length.z};
    double shifts[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    int count[3] = {1, 1, 1};
    for (int a = 0; a < 3; ++a) {
      if (!periodic[a]) continue;
      if (at[a] < los[a] + reach)
        shifts[a][count[a]++] = lengths[a];
      else if (at[a] > los[a] + lengths[a] - reach)
        shifts[a][count[a]++] = -lengths[a];
    }
    for (int i = 0; i < count[0]; ++i)
      for (int j = 0; j < count[1]; ++j)
        for (int k = 0; k < count[2]; ++k) visit(DVec3{shifts[0][i], shifts[1][j], shifts[2][k]});
  }
};

}  // namespace sph::objects
