// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "mrpt_krp_plugin/inference/onnx_model.h"

namespace krp {

/// Thresholds of the decode; the defaults are ultralytics' prediction defaults, so that the
/// C++ runtime keeps exactly what `YOLO(...).predict()` keeps (pinned by the parity test).
struct PoseDecodeParams {
  float score_threshold = 0.25f;  ///< ultralytics `conf`
  float iou_threshold = 0.7f;     ///< ultralytics `iou`, per-class NMS
  int max_detections = 300;       ///< ultralytics `max_det`
};

struct DecodedKeypoint {
  float x = 0, y = 0;  ///< continuous image coordinates [px]: pixel (i, j) covers [j, j+1) x [i, i+1)
  float visibility = 0;  ///< the model's visibility probability
};

struct PoseDetection {
  float x1 = 0, y1 = 0, x2 = 0, y2 = 0;  ///< box, image pixels, clipped to the image
  float score = 0;
  int class_id = 0;  ///< zone index, in the manifest's zone order
  std::vector<DecodedKeypoint> keypoints;
};

/// Decodes YOLOv8-pose's `output0` ([1, 4 + classes + 3K, anchors]) as ultralytics does:
/// best class per anchor, score filter, per-class greedy NMS in descending score order,
/// boxes and keypoints clipped to the image. No letterbox: the image is the model's input size.
std::vector<PoseDetection> decodeYoloPose(const Tensor& output0, int num_classes, int num_keypoints, int image_width,
                                          int image_height, const PoseDecodeParams& params = {});

}  // namespace krp
