# The library others embed (docs/embedding.md): find_package(vibroimage CONFIG) gives
#   vibroimage::primitives  the models as pure math (shaders, geometry, actuator models)
#   vibroimage::storage     the file formats (.vimg, PNG, gestures' CSV through the player)
#   vibroimage::player      scenes, the offline and real-time renderers, drive sinks
#   vibroimage::realtime    the real-time core the player is built on
# Only the headers of the supported API are installed, under include/vibroimage/: the entry headers
# below and every project header they include (found by scanning their #include lines here, so the
# list cannot miss one); the rest stays private.
include(CMakePackageConfigHelpers)

set(VIMG_PUBLIC_ENTRY_HEADERS
  primitives/image.hpp primitives/shader.hpp primitives/shader_state.hpp
  primitives/touch/dot_shader.hpp primitives/touch/line_shader.hpp primitives/touch/surface_shader.hpp
  primitives/actuator/actuator_model.hpp
  storage/image_io.hpp storage/diagnostic.hpp
  primitives/gesture.hpp storage/gesture_csv.hpp
  player/scene.hpp player/offline_render.hpp player/drive_sink.hpp player/drive_sinks.hpp)

# vimg_header_closure(OUT ENTRIES...): the entries and every "dir/file.hpp" they include, transitively.
function(vimg_header_closure out)
  set(todo ${ARGN})
  set(done "")
  while(todo)
    list(POP_FRONT todo header)
    if(header IN_LIST done)
      continue()
    endif()
    if(NOT EXISTS ${PROJECT_SOURCE_DIR}/${header})
      message(FATAL_ERROR "public header ${header} does not exist")
    endif()
    list(APPEND done ${header})
    file(STRINGS ${PROJECT_SOURCE_DIR}/${header} lines REGEX "^#include \"[a-z_]+/.*\"")
    foreach(line ${lines})
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
      list(APPEND todo ${included})
    endforeach()
  endwhile()
  list(SORT done)
  set(${out} ${done} PARENT_SCOPE)
endfunction()

vimg_header_closure(VIMG_PUBLIC_HEADERS ${VIMG_PUBLIC_ENTRY_HEADERS})
foreach(header ${VIMG_PUBLIC_HEADERS})
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vibroimage/${dir}
          COMPONENT development)
endforeach()

set_target_properties(vimg_primitives PROPERTIES EXPORT_NAME primitives)
set_target_properties(vimg_storage PROPERTIES EXPORT_NAME storage)
set_target_properties(vimg_player PROPERTIES EXPORT_NAME player)
set_target_properties(vimg_realtime PROPERTIES EXPORT_NAME realtime)
install(TARGETS vimg_primitives vimg_storage vimg_player vimg_realtime EXPORT vibroimageTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vibroimage)
install(EXPORT vibroimageTargets NAMESPACE vibroimage:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/vibroimage
        COMPONENT development)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/vibroimageConfig.cmake.in
  ${PROJECT_BINARY_DIR}/vibroimageConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/vibroimage)
# 0.x: a minor version may change the API (docs/embedding.md), so only the same minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vibroimageConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vibroimageConfig.cmake ${PROJECT_BINARY_DIR}/vibroimageConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/vibroimage COMPONENT development)
