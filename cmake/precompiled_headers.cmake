# Headers that most sources include and that each cost seconds to parse (Eigen, nlohmann's
# JSON): compiled once per build and shared by the targets, which saves minutes on a
# two-core machine (CI builds the tree twice, once with the sanitizers).
add_library(isurface_common_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/precompiled_headers.cpp)
target_link_libraries(isurface_common_pch PRIVATE Eigen3::Eigen nlohmann_json::nlohmann_json)
target_precompile_headers(isurface_common_pch PRIVATE
  <algorithm> <memory> <string> <vector> <Eigen/Core> <nlohmann/json.hpp>)

