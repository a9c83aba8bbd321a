// The mechanism of a random robot: its chain, outlines, bodies and held pieces, FRC-sized (reaches
// of 0.3-1.8 m, elevators up to 1.5 m, pivots over 90-300 degrees, 1-8 kg per link).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "random_robot_chain.hpp"

namespace cyber::test::random_robot {
namespace {

using planner::JointType;
using planner::Point2;

constexpr double kDeg = std::numbers::pi / 180.0;
// No point of the chain reaches further than this from the first joint (issue 34's FRC size).
constexpr double kMaxReachM = 1.8;

// A bar along the link's x axis from a little behind its joint to its tip, with a block at the tip.
std::vector<Polygon> bar(Draws& d, double from_m, double tip_m) {
  const double half_width_m = d.rounded(0.025, 0.06);
  const double block_m = d.rounded(0.04, 0.1);
  return {box(from_m, -half_width_m, tip_m, half_width_m),
          box(tip_m - block_m, -half_width_m - 0.02, tip_m, half_width_m + 0.02)};
}

Body linkBody(Draws& d, double from_m, double tip_m) {
  Body b;
  b.mass_kg = d.rounded(1.0, 8.0, 100.0);
  b.cg_m = Point2(std::round((from_m + (tip_m - from_m) * d.uniform(0.35, 0.65)) * 1000.0) / 1000.0, 0.0);
  b.moi_kgm2 = std::round(b.mass_kg * (tip_m - from_m) * (tip_m - from_m) / 12.0 * 1e4) / 1e4;
  return b;
}

// A pivot's range: 90-300 degrees about a drawn centre, in rad.
planner::JointRange pivotRange(Draws& d, double centre_lo_deg, double centre_hi_deg) {
  const double span_rad = d.uniform(90.0, 300.0) * kDeg;
  const double centre_rad = d.uniform(centre_lo_deg, centre_hi_deg) * kDeg;
  return {std::round((centre_rad - 0.5 * span_rad) * 1000.0) / 1000.0,
          std::round((centre_rad + 0.5 * span_rad) * 1000.0) / 1000.0};
}

JointDraw firstJoint(Draws& d, JointType type, double body_height_m, double reach_left_m, bool last) {
  JointDraw j;
  j.type = type;
  if (type == JointType::kPrismatic) {
    // An elevator: a carriage on a rail 60-90 degrees from the floor, above the robot body.
    j.origin_m = Point2(d.rounded(-0.3, 0.1), tidy(body_height_m + d.rounded(0.08, 0.2)));
    j.axis_deg = d.rounded(60.0, 90.0, 10.0);
    j.range = {0.0, d.rounded(0.4, 1.5)};
    const double half_m = d.rounded(0.05, 0.1);
    j.outline = {box(-half_m, -half_m, half_m, half_m)};
    j.body = Body{d.rounded(1.0, 8.0, 100.0), Point2::Zero(), d.rounded(0.01, 0.05, 1e4)};
    j.tip_m = last ? half_m : 0.0;
    return j;
  }
  // A pivot on a tower above the robot body, mostly pointing up and forward.
  j.origin_m = Point2(d.rounded(-0.3, 0.15), tidy(body_height_m + d.rounded(0.1, 0.5)));
  j.range = pivotRange(d, 20.0, 160.0);
  j.tip_m = d.rounded(0.3, std::min(last ? 0.8 : 0.9, reach_left_m));
  j.outline = bar(d, -d.rounded(0.04, 0.1), j.tip_m);
  j.body = linkBody(d, 0.0, j.tip_m);
  return j;
}

JointDraw nextJoint(Draws& d, const JointDraw& parent, JointType type, double reach_left_m, bool last) {
  JointDraw j;
  j.type = type;
  const bool on_pivot = parent.type == JointType::kRevolute;
  if (type == JointType::kRevolute) {
    // An elbow at the parent's tip (relative angle, any centre), or an arm on a carriage.
    j.origin_m = on_pivot ? Point2(parent.tip_m, 0.0) : Point2(d.rounded(-0.05, 0.1), d.rounded(-0.05, 0.1));
    j.range = on_pivot ? pivotRange(d, -180.0, 180.0) : pivotRange(d, 0.0, 360.0);
    j.tip_m = d.rounded(std::min(0.25, reach_left_m), std::min(last ? 0.8 : 0.9, reach_left_m));
    j.outline = bar(d, -d.rounded(0.04, 0.1), j.tip_m);
    j.body = linkBody(d, 0.0, j.tip_m);
    return j;
  }
  // A telescope sliding along its pivot's link, or an extension on a carriage, 0-20 degrees up.
  j.axis_deg = on_pivot ? 0.0 : d.rounded(-10.0, 20.0, 10.0);
  const double stage_m =
      on_pivot ? std::round(parent.tip_m * d.uniform(0.8, 1.0) * 1000.0) / 1000.0 : d.rounded(0.3, 0.6);
  j.range = {0.0, d.rounded(std::min(0.2, reach_left_m), std::max(0.2, std::min(0.9, reach_left_m)))};
  j.tip_m = stage_m;
  j.outline = bar(d, on_pivot ? 0.0 : -0.1, stage_m);
  j.body = linkBody(d, 0.0, stage_m);
  return j;
}

// How far the link takes the chain's reach (a pivot's tip, a stage's tip at full travel).
double reachOf(const JointDraw& j) { return j.type == JointType::kPrismatic ? j.range.max + j.tip_m : j.tip_m; }

}  // namespace

std::vector<JointDraw> drawChain(Draws& d, int joint_count, double body_height_m) {
  std::vector<JointDraw> chain;
  double reach_left_m = kMaxReachM - 0.3;  // room for a held piece
  std::string kinds;
  for (int i = 0; i < joint_count; ++i) {
    const bool last = i + 1 == joint_count;
    const JointType type = d.chance(i == 0 ? 0.4 : 0.35) ? JointType::kPrismatic : JointType::kRevolute;
    JointDraw j = i == 0 ? firstJoint(d, type, body_height_m, reach_left_m, last)
                         : nextJoint(d, chain.back(), type, reach_left_m, last);
    j.name = fmt::format("joint{}", i);
    // An elevator's travel lifts the chain rather than reaching out with it.
    if (!(i == 0 && type == JointType::kPrismatic)) reach_left_m = std::max(0.25, reach_left_m - reachOf(j));
    chain.push_back(std::move(j));
  }
  return chain;
}

std::vector<PieceDraw> drawPieces(Draws& d, const JointDraw& last) {
  std::vector<PieceDraw> pieces;
  const int count = d.integer(1, 2);
  for (int k = 0; k < count; ++k) {
    PieceDraw p;
    p.name = fmt::format("piece{}", k);
    const double size_m = d.rounded(0.1, 0.3);
    const double near_m = tidy(last.tip_m - d.rounded(0.0, 0.08));
    if (d.chance(0.5)) {
      p.polygon = box(near_m, -0.5 * size_m, near_m + size_m, 0.5 * size_m);
    } else {
      // A ball: an octagon around its centre.
      const Point2 centre(near_m + 0.5 * size_m, 0.0);
      for (int v = 0; v < 8; ++v) {
        const double a = (v + 0.5) * std::numbers::pi / 4.0;
        p.polygon.emplace_back(tidy(centre.x() + 0.5 * size_m * std::cos(a)), tidy(0.5 * size_m * std::sin(a)));
      }
    }
    p.body = Body{d.rounded(0.1, 1.5, 100.0), Point2(tidy(near_m + 0.5 * size_m), 0.0), 0.0};
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace cyber::test::random_robot
