# Declares the imported target `onnxruntime::onnxruntime`.
# Debian's onnxruntimeConfig.cmake references ONNX::onnx and cpuinfo, which bookworm lacks,
# so the target is declared here from the layout scripts/install_deps.sh produces.
find_library(KRP_ORT_LIBRARY NAMES onnxruntime libonnxruntime.so.1
             PATHS "${KRP_ONNXRUNTIME_ROOT}/lib" NO_DEFAULT_PATH)
find_path(KRP_ORT_INCLUDE_DIR onnxruntime_cxx_api.h
          PATHS "${KRP_ONNXRUNTIME_ROOT}/include" NO_DEFAULT_PATH)
if(NOT KRP_ORT_LIBRARY OR NOT KRP_ORT_INCLUDE_DIR)
  message(FATAL_ERROR "onnxruntime not found under ${KRP_ONNXRUNTIME_ROOT}: run scripts/install_deps.sh "
                      "or set KRP_ONNXRUNTIME_ROOT")
endif()
add_library(onnxruntime::onnxruntime SHARED IMPORTED GLOBAL)
set_target_properties(onnxruntime::onnxruntime PROPERTIES
  IMPORTED_LOCATION "${KRP_ORT_LIBRARY}"
  IMPORTED_SONAME "libonnxruntime.so.1"
  INTERFACE_INCLUDE_DIRECTORIES "${KRP_ORT_INCLUDE_DIR}")
message(STATUS "onnxruntime: ${KRP_ORT_LIBRARY}")
