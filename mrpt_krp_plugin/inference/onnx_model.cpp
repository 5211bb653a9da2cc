// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/onnx_model.h"

#include <onnxruntime_cxx_api.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {

// One environment per process, as onnxruntime requires; warnings only, so runs stay quiet.
Ort::Env& environment() {
  static Ort::Env env(ORT_LOGGING_LEVEL_ERROR, "mrpt_krp_plugin");
  return env;
}

std::string shapeText(const std::vector<int64_t>& shape) {
  std::ostringstream s;
  s << "[";
  for (size_t i = 0; i < shape.size(); ++i) s << (i ? ", " : "") << shape[i];
  s << "]";
  return s.str();
}

}  // namespace

struct OnnxModel::Session {
  Ort::Session session{nullptr};
};

OnnxModelFile readOnnxModelFile(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "model file not found");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "model file cannot be read");
  OnnxModelFile file{path, std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
  if (in.bad()) throw InputError(path, "model file could not be read to its end");
  return file;
}

OnnxModel::OnnxModel(const std::string& path, const OnnxRuntimeParams& params)
    : OnnxModel(readOnnxModelFile(path), params) {}

OnnxModel::OnnxModel(const OnnxModelFile& file, const OnnxRuntimeParams& params)
    : path_(file.path), session_(std::make_unique<Session>()) {
  const std::string& path = file.path;
  Ort::SessionOptions options;
  options.SetIntraOpNumThreads(params.intra_op_threads);
  options.SetInterOpNumThreads(params.inter_op_threads);
  options.SetExecutionMode(ExecutionMode::ORT_SEQUENTIAL);
  options.SetGraphOptimizationLevel(GraphOptimizationLevel::ORT_ENABLE_ALL);
  try {
    session_->session = Ort::Session(environment(), file.bytes.data(), file.bytes.size(), options);
  } catch (const Ort::Exception& e) {
    throw InputError(path, std::string("not a model onnxruntime can load: ") + e.what());
  }
  auto& s = session_->session;
  if (s.GetInputCount() != 1 || s.GetOutputCount() != 1)
    throw InputError(path, "expected one input and one output, found " + std::to_string(s.GetInputCount()) +
                               " and " + std::to_string(s.GetOutputCount()));
  Ort::AllocatorWithDefaultOptions alloc;
  input_name_ = s.GetInputNameAllocated(0, alloc).get();
  output_name_ = s.GetOutputNameAllocated(0, alloc).get();
  // The shape info is a view into the type info, which must outlive it.
  const Ort::TypeInfo type_info = s.GetInputTypeInfo(0);
  const auto info = type_info.GetTensorTypeAndShapeInfo();
  if (info.GetElementType() != ONNX_TENSOR_ELEMENT_DATA_TYPE_FLOAT)
    throw InputError(path, "input '" + input_name_ + "' is not float32");
  input_shape_ = info.GetShape();
}

OnnxModel::~OnnxModel() = default;

Tensor OnnxModel::run(const Tensor& input) const {
  if (input.shape.size() != input_shape_.size())
    throw InputError(path_, "input of shape " + shapeText(input.shape) + " for a model expecting " +
                                shapeText(input_shape_));
  size_t count = 1;
  for (size_t i = 0; i < input.shape.size(); ++i) {
    if (input_shape_[i] >= 0 && input_shape_[i] != input.shape[i])
      throw InputError(path_, "input of shape " + shapeText(input.shape) + " for a model expecting " +
                                  shapeText(input_shape_));
    count *= static_cast<size_t>(input.shape[i]);
  }
  if (count != input.values.size())
    throw InputError(path_, "input has " + std::to_string(input.values.size()) + " values for shape " +
                                shapeText(input.shape));
  const auto memory = Ort::MemoryInfo::CreateCpu(OrtArenaAllocator, OrtMemTypeDefault);
  // onnxruntime takes a non-const pointer but does not write to inputs.
  auto in = Ort::Value::CreateTensor<float>(memory, const_cast<float*>(input.values.data()), input.values.size(),
                                            input.shape.data(), input.shape.size());
  const char* in_names[] = {input_name_.c_str()};
  const char* out_names[] = {output_name_.c_str()};
  auto outputs = session_->session.Run(Ort::RunOptions{nullptr}, in_names, &in, 1, out_names, 1);
  const auto out_info = outputs.front().GetTensorTypeAndShapeInfo();
  Tensor out;
  out.shape = out_info.GetShape();
  const float* data = outputs.front().GetTensorData<float>();
  out.values.assign(data, data + out_info.GetElementCount());
  return out;
}

}  // namespace krp
