// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/sim/world_builders.h"

#include <algorithm>
#include <cmath>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/sim/floor_plan.h"
#include "mrpt_krp_plugin/zones/auto_zoning.h"

namespace krp {
namespace {
constexpr double kDoorWidthM = 0.9;
constexpr double kMargin = 1.0;  ///< unknown border around each building [m]

// Rooms between y0 and y1 along x in [x_start, x_end), walls between them, one door each
// onto the corridor wall at y = door_wall_y. Returns the x of each wall between two rooms.
std::vector<double> roomRow(FloorPlan& plan, Rng& rng, double x_start, double x_end, double y0, double y1, double door_wall_y,
             double min_w, double max_w, bool furnish) {
  plan.wall(x_start, door_wall_y, x_end, door_wall_y);
  std::vector<double> room_walls;
  double x = x_start;
  while (x < x_end - 0.5) {
    double w = rng.uniform(min_w, max_w);
    if (x_end - (x + w) < min_w) w = x_end - x;
    const double door = rng.uniform(x + 0.6, x + w - 0.6 - kDoorWidthM);
    plan.free(door, door_wall_y - 0.2, door + kDoorWidthM, door_wall_y + 0.2);
    if (x + w < x_end - 0.01) {
      plan.wall(x + w, y0, x + w, y1);
      room_walls.push_back(x + w);
    }
    if (furnish && rng.bernoulli(0.7)) {
      // A desk or cabinet against the far wall: mapped furniture that makes rooms differ.
      const double fw = rng.uniform(0.8, std::min(2.0, w - 1.5)), fd = rng.uniform(0.5, 0.9);
      const double fx = rng.uniform(x + 0.4, x + w - 0.4 - fw);
      const bool far_is_high = y1 > door_wall_y + 0.1;
      const double far = far_is_high ? y1 : y0;
      if (far_is_high) plan.solid(fx, far - fd - 0.1, fx + fw, far - 0.1);
      else plan.solid(fx, far + 0.1, fx + fw, far + fd + 0.1);
    }
    x += w;
  }
  return room_walls;
}

// The line (a wall, an aisle's centre) nearest to `target`, so that a zone boundary runs along the
// building's structure instead of through a room or a rack (a room cut in two shows the classifier
// the same walls under two zone names). With no line to follow, the boundary stays at `target`.
double nearestLine(const std::vector<double>& lines, double target) {
  if (lines.empty()) return target;
  return *std::min_element(lines.begin(), lines.end(), [target](double a, double b) {
    return std::abs(a - target) < std::abs(b - target);
  });
}
}  // namespace

Zone rectangleZone(const std::string& name, double x0, double y0, double x1, double y1, double res) {
  // Corners sit on cell centres, so no division lands on a cell edge where rounding decides.
  const double lx = x0 + res / 2, ly = y0 + res / 2, hx = x1 - res / 2, hy = y1 - res / 2;
  return Zone{name, {{lx, ly}, {hx, ly}, {hx, hy}, {lx, hy}}};
}

namespace {
constexpr double kOfficeWidthM = 34.0, kOfficeHeightM = 22.0;
constexpr double kOfficeCorridorLo = 9.5, kOfficeCorridorHi = 12.0;  ///< corridor walls above the office's floor [m]

// office_two_zone's building, drawn at (kMargin, kMargin) on `plan` (which may be larger), and
// its two wings as zones, which reach the edges of the office's own canvas whatever `plan`'s
// size, so a larger world holds the same two zones.
std::vector<Zone> drawOffice(FloorPlan& plan, Rng& rng) {
  const double w = kOfficeWidthM, h = kOfficeHeightM;
  const double x0 = kMargin, y0 = kMargin, x1 = kMargin + w, y1 = kMargin + h;
  plan.building(x0, y0, x1, y1);
  const double corridor_lo = y0 + kOfficeCorridorLo, corridor_hi = y0 + kOfficeCorridorHi;
  const auto north_walls = roomRow(plan, rng, x0, x1, corridor_hi, y1, corridor_hi, 4.0, 7.5, true);
  const auto south_walls = roomRow(plan, rng, x0, x1, y0, corridor_lo, corridor_lo, 4.0, 7.5, true);
  // An open lounge in the right wing: one wider gap in the lower corridor wall.
  plan.free(x0 + 24.0, corridor_lo - 0.2, x0 + 27.0, corridor_lo + 0.2);
  // The wings meet at the room walls nearest the middle; the corridor, with no wall to follow,
  // is split at the middle.
  const double mid = x0 + w / 2, north = nearestLine(north_walls, mid), south = nearestLine(south_walls, mid);
  const double r = kWorldResolutionM / 2, W = w + 2 * kMargin, H = h + 2 * kMargin;
  // Corners half a cell inside each zone, as in rectangleZone, so the two polygons never claim
  // the same cell; a step's half-cell goes to the side of whichever zone lies beyond it.
  const double south_side = south > mid ? 1.0 : -1.0, north_side = north > mid ? 1.0 : -1.0;
  const double west_lo = corridor_lo - south_side * r, east_lo = corridor_lo + south_side * r;
  const double west_hi = corridor_hi + north_side * r, east_hi = corridor_hi - north_side * r;
  return {Zone{"west_wing",
               {{r, r}, {south - r, r}, {south - r, west_lo}, {mid - r, west_lo}, {mid - r, west_hi},
                {north - r, west_hi}, {north - r, H - r}, {r, H - r}}},
          Zone{"east_wing",
               {{south + r, r}, {W - r, r}, {W - r, H - r}, {north + r, H - r}, {north + r, east_hi},
                {mid + r, east_hi}, {mid + r, east_lo}, {south + r, east_lo}}}};
}
}  // namespace

BuiltWorld buildOfficeTwoZone(uint64_t seed) {
  Rng rng(seed);
  FloorPlan plan(kOfficeWidthM + 2 * kMargin, kOfficeHeightM + 2 * kMargin, kWorldResolutionM);
  auto zones = drawOffice(plan, rng);
  return BuiltWorld{"office_two_zone", plan.toGrid(), std::move(zones), ""};
}

BuiltWorld buildOfficeUnseenWing(uint64_t seed) {
  Rng rng(seed);  // the office's own draws come first, so its rooms match office_two_zone's
  constexpr double kWingWidthM = 16.0;
  FloorPlan plan(kOfficeWidthM + kWingWidthM + 2 * kMargin, kOfficeHeightM + 2 * kMargin, kWorldResolutionM);
  auto zones = drawOffice(plan, rng);
  // The wing shares the office's east wall; a door where the corridor ends leads into it, its
  // jambs clear of the corridor's corners so the office's landmarks stay on walls.
  const double x1 = kMargin + kOfficeWidthM, x2 = x1 + kWingWidthM, y0 = kMargin, y1 = kMargin + kOfficeHeightM;
  plan.building(x1, y0, x2, y1);
  const double door_lo = y0 + (kOfficeCorridorLo + kOfficeCorridorHi - kDoorWidthM) / 2;
  plan.free(x1 - 0.2, door_lo, x1 + 0.2, door_lo + kDoorWidthM);
  // Open plan, unlike any office room: rows of columns and free-standing partitions.
  Rng wing_rng(deriveSeed(seed, 0x756e7365656eull));
  for (double cx = x1 + 4.0; cx < x2 - 1.0; cx += 4.0)
    for (double cy = y0 + 4.0; cy < y1 - 1.0; cy += 5.0) plan.solid(cx - 0.25, cy - 0.25, cx + 0.25, cy + 0.25);
  for (int i = 0; i < 4; ++i) {
    const double px = wing_rng.uniform(x1 + 2.0, x2 - 4.0), py = wing_rng.uniform(y0 + 2.0, y1 - 2.0);
    if (wing_rng.bernoulli(0.5)) plan.wall(px, py, px + wing_rng.uniform(1.5, 3.0), py);
    else plan.wall(px, py, px, std::min(y1 - 1.0, py + wing_rng.uniform(1.5, 3.0)));
  }
  const double office_canvas_w = kOfficeWidthM + 2 * kMargin, H = kOfficeHeightM + 2 * kMargin;
  zones.push_back(rectangleZone("unseen_wing", office_canvas_w, 0.0, x2 + kMargin, H, kWorldResolutionM));
  return BuiltWorld{"office_unseen_wing", plan.toGrid(), std::move(zones), "unseen_wing"};
}

BuiltWorld buildWarehouse(uint64_t seed) {
  Rng rng(seed);
  const double w = 64.0, h = 44.0;
  FloorPlan plan(w + 2 * kMargin, h + 2 * kMargin, kWorldResolutionM);
  const double x0 = kMargin, y0 = kMargin;
  plan.building(x0, y0, x0 + w, y0 + h);
  // Two blocks of identical racks: 1.1 m deep, 3.0 m aisles, an 8 m cross aisle between.
  constexpr double kRackDepth = 1.1, kAislePitch = 4.1, kRackLength = 24.0, kFirstRackY = 4.0;
  constexpr int kRackRows = 9;
  const double block_x[] = {x0 + 4.0, x0 + 36.0};
  std::vector<double> aisle_centres;
  for (double bx : block_x)
    for (int row = 0; row < kRackRows; ++row) {
      const double ry = y0 + kFirstRackY + row * kAislePitch;
      plan.solid(bx, ry, bx + kRackLength, ry + kRackDepth);
      if (bx == block_x[0] && row + 1 < kRackRows) aisle_centres.push_back(ry + (kRackDepth + kAislePitch) / 2);
    }
  // Building columns on a regular 8 m grid in the open areas (repetitive, as in real halls).
  for (double cx = x0 + 2.0; cx < x0 + w; cx += 8.0) {
    plan.solid(cx - 0.2, y0 + 1.8, cx + 0.2, y0 + 2.2);
    plan.solid(cx - 0.2, y0 + h - 2.2, cx + 0.2, y0 + h - 1.8);
  }
  // A loading dock niche and an office box at one end: the only asymmetric features.
  plan.free(x0 + w - 0.2, y0 + 10.0, x0 + w + 0.8, y0 + 14.0);
  plan.wall(x0 + w + 0.8, y0 + 10.0, x0 + w + 0.8, y0 + 14.0);
  plan.solid(x0 + 0.1, y0 + h - 5.0, x0 + 2.5 + rng.uniform(0.0, 0.5), y0 + h - 0.1);
  BuiltWorld out{"warehouse", plan.toGrid(), {}, ""};
  // Quadrants that follow the racks: west and east meet in the middle of the cross aisle, south
  // and north along the aisle nearest the middle, so no rack is cut in two (a rack split between
  // two zones shows the classifier the same aisle under two names).
  const double W = w + 2 * kMargin, H = h + 2 * kMargin;
  const double x_split = (block_x[0] + kRackLength + block_x[1]) / 2;
  const double y_split = nearestLine(aisle_centres, H / 2);
  const double xs[] = {0.0, x_split, W}, ys[] = {0.0, y_split, H};
  const char* names[2][2] = {{"south_west", "south_east"}, {"north_west", "north_east"}};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      out.zones.push_back(rectangleZone(names[j][i], xs[i], ys[j], xs[i + 1], ys[j + 1], kWorldResolutionM));
  return out;
}

BuiltWorld buildLargeFloor(uint64_t seed) {
  Rng rng(seed);
  const double w = 90.0, h = 60.0;
  FloorPlan plan(w + 2 * kMargin, h + 2 * kMargin, kWorldResolutionM);
  const double x0 = kMargin, y0 = kMargin;
  plan.building(x0, y0, x0 + w, y0 + h);
  // Two east-west corridors and a north-south spine; rooms fill the bands between.
  const double c1 = y0 + 18.0, c2 = y0 + 39.5, cw = 2.5, spine = x0 + 44.0;
  for (double half : {0.0, 1.0}) {
    const double xs = half == 0.0 ? x0 : spine + cw, xe = half == 0.0 ? spine : x0 + w;
    roomRow(plan, rng, xs, xe, y0, c1, c1, 5.0, 10.0, true);
    roomRow(plan, rng, xs, xe, c1 + cw, c1 + cw + 9.5, c1 + cw, 5.0, 10.0, true);
    plan.wall(xs, c1 + cw + 9.5, xe, c1 + cw + 9.5);
    roomRow(plan, rng, xs, xe, c1 + cw + 9.5, c2, c2, 5.0, 10.0, true);
    roomRow(plan, rng, xs, xe, c2 + cw, y0 + h, c2 + cw, 5.0, 10.0, true);
  }
  plan.free(spine, y0 + 0.1, spine + cw, y0 + h - 0.1);
  BuiltWorld out{"large_floor", plan.toGrid(), {}, ""};
  AutoZoningParams zp;
  zp.target_area_m2 = 250.0;
  zp.seed = seed;
  out.zones = autoZone(out.map, zp);
  return out;
}

namespace {
// A plain walled rectangle of w x h metres and nothing else, zoned into west and east halves.
BuiltWorld emptyBuilding(const std::string& name, double w, double h) {
  FloorPlan plan(w + 2 * kMargin, h + 2 * kMargin, kWorldResolutionM);
  plan.building(kMargin, kMargin, kMargin + w, kMargin + h);
  BuiltWorld out{name, plan.toGrid(), {}, ""};
  const double W = w + 2 * kMargin, H = h + 2 * kMargin;
  out.zones.push_back(rectangleZone("west_half", 0.0, 0.0, W / 2, H, kWorldResolutionM));
  out.zones.push_back(rectangleZone("east_half", W / 2, 0.0, W, H, kWorldResolutionM));
  return out;
}
}  // namespace

// Away from the closed ends a scan sees two parallel lines that fit anywhere along the corridor.
BuiltWorld buildCorridor(uint64_t /*seed*/) { return emptyBuilding("corridor", 60.0, 2.4); }

// Every pose has a twin turned by 180 degrees, and from the middle a 12 m lidar sees no wall.
BuiltWorld buildEmptyHall(uint64_t /*seed*/) { return emptyBuilding("empty_hall", 40.0, 30.0); }

const std::vector<std::string>& worldNames() {
  static const std::vector<std::string> names = {"office_two_zone", "warehouse", "large_floor", "corridor",
                                                 "empty_hall", "office_unseen_wing"};
  return names;
}

BuiltWorld buildWorld(const std::string& name, uint64_t seed) {
  if (name == "office_two_zone") return buildOfficeTwoZone(seed);
  if (name == "warehouse") return buildWarehouse(seed);
  if (name == "large_floor") return buildLargeFloor(seed);
  if (name == "corridor") return buildCorridor(seed);
  if (name == "empty_hall") return buildEmptyHall(seed);
  if (name == "office_unseen_wing") return buildOfficeUnseenWing(seed);
  std::string known;
  for (const auto& n : worldNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("world '" + name + "'", "unknown (known: " + known + ")");
}

}  // namespace krp
