# All dependencies are Debian 12 packages (scripts/install-deps.sh installs them).
find_package(OpenMP REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(FastFloat REQUIRED)  # libfast-float-dev: header only, obj_chunk.cpp
include(${CMAKE_CURRENT_LIST_DIR}/OpenImageIO.cmake)  # only in the librayvec_oiio.so module
find_package(OpenEXR 3 REQUIRED CONFIG)  # only in the librayvec_exr.so module
find_package(PNG REQUIRED)
find_package(ZLIB REQUIRED)  # zlib1g-dev: png_encoder.cpp deflates the PNGs rayvec writes
find_package(JPEG REQUIRED)  # libjpeg-dev (libjpeg-turbo): jpeg_file.cpp
find_package(nlohmann_json REQUIRED)
find_package(glm REQUIRED)
find_package(CLI11 REQUIRED)

# Embree 3 is optional: only `rayvec bench rays --vs-embree` uses it.
set(RAYVEC_HAVE_EMBREE OFF)
if(RAYVEC_WITH_EMBREE)
  find_package(embree 3 QUIET)
  if(embree_FOUND)
    set(RAYVEC_HAVE_EMBREE ON)
    message(STATUS "rayvec: Embree ${embree_VERSION} found, --vs-embree enabled")
  else()
    message(STATUS "rayvec: Embree 3 not found, --vs-embree disabled")
  endif()
endif()
