// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/zones/auto_zoning.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/grid_image.h"

namespace krp {
namespace {

constexpr int kNone = -1;
// Zones are numbered in reading order: rows of this height, then left to right [px].
constexpr double kNamingRowBandPx = 50.0;

// Gives every free pixel left unlabelled (watershed ridges) its labelled neighbour's label.
void fillUnlabelledFree(cv::Mat& labels, const cv::Mat& free) {
  for (bool changed = true; changed;) {
    changed = false;
    cv::Mat prev = labels.clone();
    for (int r = 0; r < labels.rows; ++r)
      for (int c = 0; c < labels.cols; ++c) {
        if (!free.at<uint8_t>(r, c) || prev.at<int>(r, c) >= 0) continue;
        for (int dr = -1; dr <= 1 && labels.at<int>(r, c) < 0; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int rr = r + dr, cc = c + dc;
            if (rr < 0 || cc < 0 || rr >= labels.rows || cc >= labels.cols) continue;
            if (prev.at<int>(rr, cc) >= 0) {
              labels.at<int>(r, c) = prev.at<int>(rr, cc);
              changed = true;
              break;
            }
          }
      }
  }
}

// Renumbers labels to 0..n-1 by connected pieces, so a label never names two separate pieces.
int relabelConnected(cv::Mat& labels) {
  cv::Mat out(labels.size(), CV_32S, cv::Scalar(kNone));
  double max_label;
  cv::minMaxLoc(labels, nullptr, &max_label);
  int next = 0;
  for (int l = 0; l <= static_cast<int>(max_label); ++l) {
    const cv::Mat mask = labels == l;
    if (cv::countNonZero(mask) == 0) continue;
    cv::Mat comp;
    const int n = cv::connectedComponents(mask, comp, 8, CV_32S);
    for (int k = 1; k < n; ++k) out.setTo(next++, comp == k);
  }
  labels = out;
  return next;
}

std::vector<cv::Point> outerContour(const cv::Mat& mask) {
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  if (contours.empty()) return {};
  return *std::max_element(contours.begin(), contours.end(),
                           [](const auto& a, const auto& b) { return cv::contourArea(a) < cv::contourArea(b); });
}

// Cells of other regions inside the region's outer outline (a ring's hole, or a neighbour
// reaching diagonally across the outline); empty if there are none.
cv::Mat othersInsideOutline(const cv::Mat& labels, int label) {
  const auto contour = outerContour(labels == label);
  if (contour.size() < 3) return cv::Mat::zeros(labels.size(), CV_8U);
  cv::Mat filled = cv::Mat::zeros(labels.size(), CV_8U);
  cv::fillPoly(filled, std::vector<std::vector<cv::Point>>{contour}, cv::Scalar(255));
  return (labels >= 0) & (labels != label) & filled;
}

// True if the region's outer outline also encloses cells of other regions (a ring).
bool enclosesOthers(const cv::Mat& labels, int label) { return cv::countNonZero(othersInsideOutline(labels, label)) > 0; }

void splitRegion(cv::Mat& labels, int label, int parts, int new_label_base, uint64_t seed) {
  std::vector<cv::Point> pts;
  cv::findNonZero(labels == label, pts);
  if (static_cast<int>(pts.size()) < parts * 4) return;
  cv::Mat samples(static_cast<int>(pts.size()), 2, CV_32F);
  for (int i = 0; i < samples.rows; ++i) {
    samples.at<float>(i, 0) = static_cast<float>(pts[i].x);
    samples.at<float>(i, 1) = static_cast<float>(pts[i].y);
  }
  cv::theRNG().state = seed;
  cv::Mat assignment;
  cv::kmeans(samples, parts, assignment, cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 0.5), 3,
             cv::KMEANS_PP_CENTERS);
  for (int i = 0; i < samples.rows; ++i) {
    const int a = assignment.at<int>(i);
    if (a > 0) labels.at<int>(pts[i]) = new_label_base + a - 1;
  }
}

// Merges every region below `min_cells` into the neighbour it shares the longest border with.
void mergeSmall(cv::Mat& labels, int n, double min_cells) {
  std::vector<double> area(n, 0.0);
  std::map<std::pair<int, int>, int> border;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c) {
      const int a = labels.at<int>(r, c);
      if (a < 0) continue;
      area[a] += 1;
      for (const auto& d : {cv::Point(1, 0), cv::Point(0, 1), cv::Point(1, 1), cv::Point(-1, 1)}) {
        const int rr = r + d.y, cc = c + d.x;
        if (rr >= labels.rows || cc < 0 || cc >= labels.cols) continue;
        const int b = labels.at<int>(rr, cc);
        if (b >= 0 && b != a) ++border[{std::min(a, b), std::max(a, b)}];
      }
    }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (bool merged = true; merged;) {
    merged = false;
    int smallest = -1;
    for (int l = 0; l < n; ++l)
      if (find(l) == l && area[l] < min_cells && (smallest < 0 || area[l] < area[smallest])) {
        // Only regions that have some neighbour can be merged.
        bool has_neighbour = false;
        for (const auto& [k, len] : border)
          if ((find(k.first) == l) != (find(k.second) == l)) { has_neighbour = true; break; }
        if (has_neighbour) smallest = l;
      }
    if (smallest < 0) break;
    std::map<int, int> shared;
    for (const auto& [k, len] : border) {
      const int a = find(k.first), b = find(k.second);
      if (a == b) continue;
      if (a == smallest) shared[b] += len;
      else if (b == smallest) shared[a] += len;
    }
    const auto best = std::max_element(shared.begin(), shared.end(),
                                       [](const auto& x, const auto& y) { return x.second < y.second; });
    parent[smallest] = best->first;
    area[best->first] += area[smallest];
    merged = true;
  }
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (labels.at<int>(r, c) >= 0) labels.at<int>(r, c) = find(labels.at<int>(r, c));
}

// A zone is stored as its outer outline, so every free cell inside that outline belongs to it.
// Hands such cells (enclosed regions, or cells an 8-connected neighbour reaches diagonally
// across the outline) to the enclosing region, until no outline claims another's cells.
int absorbEnclosed(cv::Mat& labels, int n, int max_rounds) {
  for (int round = 0; round < max_rounds; ++round) {
    bool changed = false;
    for (int l = 0; l < n; ++l) {
      const cv::Mat others = othersInsideOutline(labels, l);
      if (cv::countNonZero(others) == 0) continue;
      labels.setTo(l, others);
      changed = true;
    }
    n = relabelConnected(labels);
    if (!changed) break;
  }
  return n;
}

// Drops regions below `min_cells`: after merging, only isolated pockets that touch no other
// region are left that small, and no robot fits in them.
int dropTiny(cv::Mat& labels, int n, double min_cells) {
  for (int l = 0; l < n; ++l) {
    const cv::Mat mask = labels == l;
    if (cv::countNonZero(mask) < min_cells) labels.setTo(kNone, mask);
  }
  return relabelConnected(labels);
}

}  // namespace

std::vector<Zone> autoZone(const mrpt::maps::COccupancyGridMap2D& grid, const AutoZoningParams& p) {
  // A zero or negative target would zone as if it were tiny; the factors scale it.
  if (!(p.target_area_m2 > 0.0) || !std::isfinite(p.target_area_m2)) {
    std::ostringstream got;
    got << p.target_area_m2;
    throw InputError("auto-zoning", "target area must be a positive number of m^2, got " + got.str());
  }
  if (!(p.split_above_factor > p.merge_below_factor) || !(p.merge_below_factor >= 0.0))
    throw InputError("auto-zoning", "split_above_factor must exceed merge_below_factor, which must be 0 or more");
  const double res = grid.getResolution();
  const double cell_area = res * res;
  cv::Mat free = freeMask(grid, p.cells);

  // Drop tiny free islands (noise, cells inside walls).
  cv::Mat comp, stats, centroids;
  const int ncomp = cv::connectedComponentsWithStats(free, comp, stats, centroids, 8, CV_32S);
  for (int k = 1; k < ncomp; ++k)
    if (stats.at<int>(k, cv::CC_STAT_AREA) * cell_area < p.min_island_area_m2) free.setTo(0, comp == k);
  if (cv::countNonZero(free) == 0) throw InputError("auto-zoning", "the map has no free space to zone");

  // Seeds: the free space that stays connected after shrinking by the passage half-width
  // (doors and narrow passages close, rooms stay apart).
  cv::Mat dist;
  cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_5);
  dist *= res;
  cv::Mat seeds;
  int nseeds = cv::connectedComponents(dist > p.passage_half_width_m, seeds, 8, CV_32S);
  // A free component with no seed (all narrower than a door) becomes its own seed.
  for (int k = 1; k < ncomp; ++k) {
    const cv::Mat piece = (comp == k) & free;
    if (cv::countNonZero(piece) == 0) continue;
    double max_seed;
    cv::minMaxLoc(seeds, nullptr, &max_seed, nullptr, nullptr, piece);
    if (max_seed == 0) seeds.setTo(nseeds++, piece);
  }

  // Watershed on the inverted distance: basins are rooms, ridges fall in narrow passages.
  const int background = nseeds;
  cv::Mat markers = seeds.clone();
  markers.setTo(background, free == 0);
  cv::Mat elevation;
  double dmax;
  cv::minMaxLoc(dist, nullptr, &dmax);
  dist.convertTo(elevation, CV_8U, dmax > 0 ? -255.0 / dmax : 0.0, 255.0);
  cv::Mat elevation3;
  cv::cvtColor(elevation, elevation3, cv::COLOR_GRAY2BGR);
  cv::watershed(elevation3, markers);

  cv::Mat labels = markers - 1;  // seeds were 1..n; make them 0-based
  labels.setTo(kNone, (markers <= 0) | (markers == background) | (free == 0));
  fillUnlabelledFree(labels, free);
  int n = relabelConnected(labels);

  // Size towards the target: split large or ring-shaped regions, then merge small ones.
  const double target_cells = p.target_area_m2 / cell_area;
  for (int round = 0; round < p.max_split_rounds; ++round) {
    bool split_any = false;
    const int current = n;
    for (int l = 0; l < current; ++l) {
      const double cells = cv::countNonZero(labels == l);
      int parts = 0;
      if (cells > p.split_above_factor * target_cells) parts = static_cast<int>(std::lround(cells / target_cells));
      else if (enclosesOthers(labels, l)) parts = 2;
      if (parts < 2) continue;
      splitRegion(labels, l, parts, n, p.seed + static_cast<uint64_t>(l) + 1000u * round);
      n += parts - 1;
      split_any = true;
    }
    n = relabelConnected(labels);
    if (!split_any) break;
  }
  mergeSmall(labels, n, p.merge_below_factor * target_cells);
  n = relabelConnected(labels);
  n = absorbEnclosed(labels, n, p.max_split_rounds);
  n = dropTiny(labels, n, p.min_zone_area_m2 / cell_area);

  // Order zones top-left first so names are stable and readable on the picture.
  struct Region {
    int label;
    cv::Point2d centre;
  };
  std::vector<Region> regions;
  for (int l = 0; l < n; ++l) {
    const cv::Moments m = cv::moments(labels == l, true);
    if (m.m00 > 0) regions.push_back({l, {m.m10 / m.m00, m.m01 / m.m00}});
  }
  std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) {
    return std::make_pair(std::floor(a.centre.y / kNamingRowBandPx), a.centre.x) < std::make_pair(std::floor(b.centre.y / kNamingRowBandPx), b.centre.x);
  });
  std::vector<Zone> zones;
  for (const auto& r : regions) {
    const auto contour = outerContour(labels == r.label);
    if (contour.size() < 3) continue;
    Zone z;
    char name[32];
    std::snprintf(name, sizeof(name), "zone_%02zu", zones.size());
    z.name = name;
    for (const auto& px : contour) z.polygon.push_back(pixelToWorld(grid, px));
    zones.push_back(std::move(z));
  }
  return zones;
}

}  // namespace krp
