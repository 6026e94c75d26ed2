// The fluid's periodic axes as the object engine meets them. An object is never cut at a
// periodic face: its particles stay together, and the whole object is moved by a period once its
// centre has left the domain (ObjectWorld::step). So two objects may lie a period apart, and a
// pair's separation is taken to its nearest image; a search for what a particle touches runs from
// each image of its position that lies within reach of the domain.
#pragma once

#include <cmath>

#include "objects/math3d.hpp"
#include "sph/core/periodic.hpp"

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
    if (periodic[0]) x.x = intoPeriod(x.x, lo.x, length.x);
    if (periodic[1]) x.y = intoPeriod(x.y, lo.y, length.y);
    if (periodic[2]) x.z = intoPeriod(x.z, lo.z, length.z);
    return x;
  }

  // The shift by whole periods that brings the point c back inside [lo, lo + L): what moves an
  // object whose centre is c.
  DVec3 shiftInto(DVec3 c) const { return wrapped(c) - c; }

  // Calls visit(shift) for the zero shift and for each shift by a period that brings a wrapped
  // position x within `reach` of the domain from beyond the opposite face: the images to search
  // from (forEachPeriodicImage).
  template <class Visit>
  void forEachImage(DVec3 x, double reach, Visit&& visit) const {
    const double at[3] = {x.x, x.y, x.z}, los[3] = {lo.x, lo.y, lo.z};
    const double his[3] = {lo.x + length.x, lo.y + length.y, lo.z + length.z};
    forEachPeriodicImage(periodic, at, los, his, reach, [&](const int s[3]) {
      visit(DVec3{s[0] * length.x, s[1] * length.y, s[2] * length.z});
    });
  }
};

}  // namespace sph::objects
