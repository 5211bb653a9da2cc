// SPDX-License-Identifier: BSD-3-Clause
// krp-infer: runs a model folder's classifier and keypoint model on submap images, as the robot
// does, and prints JSON; or measures their latency (one thread by default).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_args.h"
#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/statistics.h"
#include "mrpt_krp_plugin/inference/keypoint_detector.h"
#include "mrpt_krp_plugin/inference/zone_classifier.h"

using krp::apps::CliArgs;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

cv::Mat readImage(const std::string& path, int mode) {
  cv::Mat img = cv::imread(path, mode);
  if (img.empty()) throw krp::InputError(path, "cannot read as an image");
  return img;
}

json detectionsJson(const std::vector<krp::PoseDetection>& dets) {
  json out = json::array();
  for (const auto& d : dets) {
    json kp = json::array();
    for (const auto& k : d.keypoints) kp.push_back({k.x, k.y, k.visibility});
    out.push_back({{"box", {d.x1, d.y1, d.x2, d.y2}}, {"score", d.score}, {"class", d.class_id}, {"keypoints", kp}});
  }
  return out;
}

constexpr double kP90 = 0.9;
/// The most --latency runs: a million runs of the keypoint model is hours already.
constexpr long long kMaxLatencyRuns = 1'000'000;

// Median and 90th percentile of `runs` timed calls, after `warmup` untimed ones.
template <typename F>
json timeCalls(F&& call, int runs, int warmup) {
  for (int i = 0; i < warmup; ++i) call();
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    call();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return {{"runs", runs}, {"median_ms", krp::median(ms)}, {"p90_ms", krp::quantile(ms, kP90)}};
}

}  // namespace

static int run(int argc, char** argv) {
  CliArgs args("krp-infer",
               "Runs the models of a krp-train-map folder on submap images (occupancy PNG for the zone classifier, "
               "SDT PNG for the keypoint model) with onnxruntime and prints the results as JSON; with --latency, "
               "measures each model's inference time instead.",
               {{"models", "DIR", "model folder with manifest.json (required)", ""},
                {"occupancy", "PNG[,PNG...]", "occupancy images for the zone classifier", ""},
                {"sdt", "PNG[,PNG...]", "SDT images for the keypoint model", ""},
                {"conf", "P", "keypoint model: score threshold (ultralytics 'conf')", "0.25"},
                {"iou", "P", "keypoint model: NMS IoU threshold (ultralytics 'iou')", "0.7"},
                {"raw-dir", "DIR", "also write each SDT image's raw output0 as <stem>.f32 (float32, row-major)", ""},
                {"threads", "N", "onnxruntime intra-op threads", "1"},
                {"latency", "RUNS", "measure latency over RUNS runs per model (0 = off)", "0"},
                {"latency-json", "FILE", "write the latency figures here (with the models' hashes)", ""}});
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("models")) throw krp::InputError("--models", "is required\n" + args.usage());
  const krp::ModelManifest manifest = krp::readModelManifest(args.get("models"));
  krp::OnnxRuntimeParams ort;
  ort.intra_op_threads = static_cast<int>(args.integer("threads"));
  const krp::ZoneClassifier classifier(manifest, ort);
  const krp::KeypointDetector detector(manifest, ort);
  krp::PoseDecodeParams decode;
  decode.score_threshold = static_cast<float>(args.number("conf"));
  decode.iou_threshold = static_cast<float>(args.number("iou"));

  const int runs = static_cast<int>(args.integerInRange("latency", 0, kMaxLatencyRuns));
  if (runs > 0) {
    // Measured on a real submap image when one is given, else on an all-unknown one: the cost of
    // these networks does not depend on the pixel values.
    const int n = manifest.submap_size_px;
    const cv::Mat occ = args.has("occupancy") ? readImage(args.list("occupancy").front(), cv::IMREAD_GRAYSCALE)
                                              : cv::Mat(n, n, CV_8UC1, cv::Scalar(128));
    const cv::Mat sdt = args.has("sdt") ? readImage(args.list("sdt").front(), cv::IMREAD_COLOR)
                                        : cv::Mat(n, n, CV_8UC3, cv::Scalar(255, 255, 255));
    const int warmup = std::max(5, runs / 20);
    auto timed = [&](auto&& call, const krp::ManifestModel& model) {
      json t = timeCalls(call, runs, warmup);
      t["file"] = model.file;
      t["sha256"] = model.sha256;
      return t;
    };
    const json models = {timed([&] { classifier.probabilities(occ); }, manifest.classifier),
                         timed([&] { detector.detect(sdt, decode); }, manifest.keypoints)};
    json out = {{"command", args.commandLine()}, {"threads", ort.intra_op_threads}, {"models", models}};
    std::cout << out.dump(2) << "\n";
    if (args.has("latency-json")) krp::writeFileAtomically(args.get("latency-json"), out.dump(2) + "\n");
    return 0;
  }

  json out = {{"world", manifest.world}, {"zones", manifest.zones}};
  json occ_results = json::array();
  for (const auto& path : args.list("occupancy")) {
    if (path.empty()) continue;
    occ_results.push_back({{"image", path},
                           {"probabilities", classifier.probabilities(readImage(path, cv::IMREAD_GRAYSCALE))}});
  }
  json sdt_results = json::array();
  for (const auto& path : args.list("sdt")) {
    if (path.empty()) continue;
    const cv::Mat img = readImage(path, cv::IMREAD_COLOR);
    const krp::Tensor raw = detector.raw(img);
    if (args.has("raw-dir")) {
      fs::create_directories(args.get("raw-dir"));
      std::ofstream f(fs::path(args.get("raw-dir")) / (fs::path(path).stem().string() + ".f32"), std::ios::binary);
      f.write(reinterpret_cast<const char*>(raw.values.data()), static_cast<std::streamsize>(raw.values.size() * 4));
      if (!f) throw krp::InputError(args.get("raw-dir"), "cannot write the raw output");
    }
    sdt_results.push_back({{"image", path}, {"detections", detectionsJson(detector.decode(raw, decode))}});
  }
  out["occupancy"] = occ_results;
  out["sdt"] = sdt_results;
  std::cout << out.dump(2) << "\n";
  return 0;
}

int main(int argc, char** argv) { return krp::apps::runMain("krp-infer", run, argc, argv); }
