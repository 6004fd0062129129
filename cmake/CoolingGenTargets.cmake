# Libraries, one per pipeline stage. Sources are globbed per folder so that adding a file needs no
# CMake edit; CONFIGURE_DEPENDS re-globs on every build.
include(GNUInstallDirs)

function(cg_add_library name)
  cmake_parse_arguments(A "" "" "DIRS;DEPS" ${ARGN})
  set(srcs)
  foreach(d IN LISTS A_DIRS)
    file(GLOB_RECURSE s CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${d}/*.cpp)
    list(APPEND srcs ${s})
  endforeach()
  list(FILTER srcs EXCLUDE REGEX "/src/cli/")
  if(NOT srcs)
    # Stage not written yet: an empty archive keeps the link graph stable.
    set(srcs ${PROJECT_SOURCE_DIR}/cmake/empty.cpp)
  endif()
  add_library(${name} STATIC ${srcs})
  add_library(coolinggen::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/coolinggen>)
  target_link_libraries(${name} PUBLIC ${A_DEPS})
endfunction()

# NURBS kernel, geometric algorithms and edge-orthogonal patches: Eigen only, no OCCT.
cg_add_library(coolinggen_kernel DIRS src/core src/modify src/analyze src/fit src/algo src/ortho DEPS Eigen3::Eigen)
# Exact conversion to and from OCCT geometry.
cg_add_library(coolinggen_adaptors DIRS adaptors DEPS coolinggen_kernel coolinggen_occt_deps)

# Blade model: meridional net, sections, blade surface, blade-relative coordinates, structured grids
# (no OCCT).
cg_add_library(coolinggen_model DIRS src/blade src/grid DEPS coolinggen_kernel)
# B-rep solids, verification and the cooling features (OCCT).
cg_add_library(coolinggen_brep DIRS src/brep features DEPS coolinggen_model coolinggen_adaptors nlohmann_json::nlohmann_json)
# Output files: STEP, IGES, BREP, STL, VTK, previews, reports, grid files (OCCT, VTK, CGNS).
cg_add_library(coolinggen_export DIRS export DEPS coolinggen_brep coolinggen_vtk_deps coolinggen_cgns_deps nlohmann_json::nlohmann_json)
vtk_module_autoinit(TARGETS coolinggen_export MODULES ${VTK_LIBRARIES})
target_compile_definitions(coolinggen_export PRIVATE COOLINGGEN_VERSION="${PROJECT_VERSION}")
# report.html's viewer (three.js, bundled once and committed), page script and style (export/web/).
include(${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake)
cg_embed_text(coolinggen_export OUTPUT ${PROJECT_BINARY_DIR}/generated/web_assets.cpp NAMESPACE cg::io::web
  ENTRIES kViewerBundle export/web/viewer.bundle.js kReportPage export/web/report_page.js
  kStudyPage export/web/study_page.js kPageStyle export/web/report.css)
# Meshing through gmsh's C++ API (gmsh takes the OCCT shape); mesh.cgns with export's CGNS file helpers.
cg_add_library(coolinggen_mesh DIRS src/mesh DEPS coolinggen_brep coolinggen_export coolinggen_gmsh_deps coolinggen_vtk_deps)
vtk_module_autoinit(TARGETS coolinggen_mesh MODULES ${VTK_LIBRARIES})
# Blades designed by other tools (geomTurbo): read, checked, cut at our streamlines into the model's
# point sections, fidelity measured (no OCCT).
cg_add_library(coolinggen_import DIRS src/blade_import DEPS coolinggen_model)
# Blades given as CAD (STEP, IGES): read by OCCT, their faces cut at our stream surfaces into the
# import's section outlines and sampled for its fidelity.
cg_add_library(coolinggen_cad_import DIRS src/cad_import DEPS coolinggen_import coolinggen_brep)
# Configuration file (JSON) -> plain option structs and the blade model's definitions (no OCCT in its
# reader; build_model's import of a STEP / IGES blade goes through coolinggen_cad_import).
cg_add_library(coolinggen_config DIRS src/config DEPS coolinggen_import coolinggen_cad_import coolinggen_model nlohmann_json::nlohmann_json)
# The coolant circuit of a built part as a flow network, solved by CalculiX (ccx) in a child process.
cg_add_library(coolinggen_network DIRS src/network DEPS coolinggen_brep coolinggen_config nlohmann_json::nlohmann_json)
# The whole job (config -> verified, exported model) as a library call; the CLI is a thin layer on it.
cg_add_library(coolinggen_pipeline DIRS src/pipeline DEPS OpenSSL::Crypto coolinggen_config coolinggen_export coolinggen_mesh
  coolinggen_network)

add_library(coolinggen INTERFACE)
add_library(coolinggen::coolinggen ALIAS coolinggen)
target_link_libraries(coolinggen INTERFACE coolinggen_pipeline coolinggen_network coolinggen_config coolinggen_mesh coolinggen_export
  coolinggen_brep coolinggen_cad_import coolinggen_import coolinggen_model coolinggen_adaptors coolinggen_kernel)

# The CLI: its commands in a library (tests/cli links it to test them without a process), main.cpp
# in the executable.
file(GLOB cli_srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/cli/*.cpp)
list(FILTER cli_srcs EXCLUDE REGEX "/src/cli/main\\.cpp$")
add_library(coolinggen_cli_commands STATIC ${cli_srcs})
target_link_libraries(coolinggen_cli_commands PUBLIC coolinggen CLI11::CLI11 TBB::tbb)
# The commands' file-writing jobs (src/cli/output_jobs.hpp): called directly by the CLI tests
# (coolinggen_cli_linked_jobs); the executable loads them from the output module on first use, so that it
# starts without VTK, gmsh, CGNS and OCCT's data exchange (--as-needed drops those libraries from it); it
# looks for the module in its own folder (the build folder), then in <prefix>/<libdir>/coolinggen.
add_library(coolinggen_cli_linked_jobs STATIC ${PROJECT_SOURCE_DIR}/src/cli/output_jobs/linked.cpp)
target_link_libraries(coolinggen_cli_linked_jobs PUBLIC coolinggen_cli_commands)
add_library(coolinggen_outputs MODULE ${PROJECT_SOURCE_DIR}/src/cli/output_jobs/module.cpp
  ${PROJECT_SOURCE_DIR}/src/cli/output_jobs/linked.cpp)
target_link_libraries(coolinggen_outputs PRIVATE coolinggen)
# -Bsymbolic: the module's code calls its own copies of the pipeline, never the executable's.
target_link_options(coolinggen_outputs PRIVATE -Wl,-Bsymbolic -Wl,--no-undefined)
set_target_properties(coolinggen_outputs PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR})
add_executable(coolinggen_cli ${PROJECT_SOURCE_DIR}/src/cli/main.cpp ${PROJECT_SOURCE_DIR}/src/cli/output_jobs/loaded.cpp)
set_target_properties(coolinggen_cli PROPERTIES OUTPUT_NAME coolinggen RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR})
file(RELATIVE_PATH cg_module_dir ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_LIBDIR}/coolinggen)
target_compile_definitions(coolinggen_cli PRIVATE COOLINGGEN_MODULE_DIR="${cg_module_dir}")
target_link_libraries(coolinggen_cli PRIVATE coolinggen_cli_commands ${CMAKE_DL_LIBS})
target_link_options(coolinggen_cli PRIVATE -Wl,--as-needed)
add_dependencies(coolinggen_cli coolinggen_outputs)
install(TARGETS coolinggen_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS coolinggen_outputs LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/coolinggen)

install(TARGETS coolinggen coolinggen_pipeline coolinggen_network coolinggen_config coolinggen_mesh coolinggen_export coolinggen_brep
  coolinggen_import coolinggen_cad_import coolinggen_model coolinggen_kernel coolinggen_adaptors coolinggen_occt_deps coolinggen_vtk_deps coolinggen_gmsh_deps
  coolinggen_cgns_deps
  EXPORT CoolingGenTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(d src adaptors features export)
  install(DIRECTORY ${d}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/coolinggen/${d}
    FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(EXPORT CoolingGenTargets NAMESPACE coolinggen:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/CoolingGen)
include(CMakePackageConfigHelpers)
configure_package_config_file(cmake/CoolingGenConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/CoolingGenConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/CoolingGen)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/CoolingGenConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/CoolingGenConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/CoolingGenConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/CoolingGen)
