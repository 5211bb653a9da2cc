// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/yolo_pose_decode.h"

#include <algorithm>
#include <numeric>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {

// ultralytics separates classes by shifting each class's boxes by class x 7680 px before one NMS;
// the shift is applied here too so that the rounding near the threshold is the same.
constexpr float kClassOffsetPx = 7680.0f;

float iou(const PoseDetection& a, const PoseDetection& b) {
  const float oa = static_cast<float>(a.class_id) * kClassOffsetPx;
  const float ob = static_cast<float>(b.class_id) * kClassOffsetPx;
  const float w = std::max(0.0f, std::min(a.x2 + oa, b.x2 + ob) - std::max(a.x1 + oa, b.x1 + ob));
  const float h = std::max(0.0f, std::min(a.y2 + oa, b.y2 + ob) - std::max(a.y1 + oa, b.y1 + ob));
  const float inter = w * h;
  const float area_a = ((a.x2 + oa) - (a.x1 + oa)) * ((a.y2 + oa) - (a.y1 + oa));
  const float area_b = ((b.x2 + ob) - (b.x1 + ob)) * ((b.y2 + ob) - (b.y1 + ob));
  return inter / (area_a + area_b - inter);
}

float clip(float v, float hi) { return std::min(std::max(v, 0.0f), hi); }

}  // namespace

std::vector<PoseDetection> decodeYoloPose(const Tensor& output0, int num_classes, int num_keypoints, int image_width,
                                          int image_height, const PoseDecodeParams& params) {
  const int channels = 4 + num_classes + 3 * num_keypoints;
  if (output0.shape.size() != 3 || output0.shape[0] != 1 || output0.shape[1] != channels)
    throw InputError("keypoint model output", "expected shape [1, " + std::to_string(channels) +
                                                  ", anchors] for " + std::to_string(num_classes) + " zones and " +
                                                  std::to_string(num_keypoints) + " keypoints");
  const int anchors = static_cast<int>(output0.shape[2]);
  auto at = [&](int c, int a) { return output0.values[static_cast<size_t>(c) * anchors + a]; };

  std::vector<PoseDetection> candidates;
  for (int a = 0; a < anchors; ++a) {
    int best = 0;
    for (int c = 1; c < num_classes; ++c)
      if (at(4 + c, a) > at(4 + best, a)) best = c;
    const float score = at(4 + best, a);
    if (!(score > params.score_threshold)) continue;
    PoseDetection d;
    const float cx = at(0, a), cy = at(1, a), w = at(2, a), h = at(3, a);
    // Unclipped during NMS, as ultralytics; clipped afterwards when scaled to the image.
    d.x1 = cx - w / 2;
    d.y1 = cy - h / 2;
    d.x2 = cx + w / 2;
    d.y2 = cy + h / 2;
    d.score = score;
    d.class_id = best;
    d.keypoints.resize(num_keypoints);
    for (int k = 0; k < num_keypoints; ++k) {
      const int base = 4 + num_classes + 3 * k;
      d.keypoints[k] = {at(base, a), at(base + 1, a), at(base + 2, a)};
    }
    candidates.push_back(std::move(d));
  }
  std::vector<size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t i, size_t j) { return candidates[i].score > candidates[j].score; });

  std::vector<PoseDetection> kept;
  std::vector<bool> suppressed(candidates.size(), false);
  for (size_t oi = 0; oi < order.size() && static_cast<int>(kept.size()) < params.max_detections; ++oi) {
    const size_t i = order[oi];
    if (suppressed[i]) continue;
    kept.push_back(candidates[i]);
    for (size_t oj = oi + 1; oj < order.size(); ++oj) {
      const size_t j = order[oj];
      if (!suppressed[j] && candidates[j].class_id == candidates[i].class_id &&
          iou(candidates[i], candidates[j]) > params.iou_threshold)
        suppressed[j] = true;
    }
  }
  const float w = static_cast<float>(image_width), h = static_cast<float>(image_height);
  for (auto& d : kept) {
    d.x1 = clip(d.x1, w);
    d.x2 = clip(d.x2, w);
    d.y1 = clip(d.y1, h);
    d.y2 = clip(d.y2, h);
    for (auto& k : d.keypoints) {
      k.x = clip(k.x, w);
      k.y = clip(k.y, h);
    }
  }
  return kept;
}

}  // namespace krp
