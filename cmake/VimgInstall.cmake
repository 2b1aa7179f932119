# Installing (issue: install it like real software). `cmake --install BUILD --prefix P` puts
#   P/bin                          the programs
#   P/share/vibroimage             the shipped profiles, examples and gestures (storage/shipped_data.hpp
#                                  finds them from the program's own location: ../share/vibroimage)
#   P/share/doc/vibroimage         the docs
#   P/share/man/man1               one man page per program (gzipped), made at build time from its --help
#   P/share/applications, P/share/mime/packages, P/share/icons/hicolor/scalable/apps
#                                  the editor's desktop entry, the .vimg MIME type and the icon
#   P/lib/udev/rules.d             the device access rules (docs/hardware.md)
# The build tree gets the same share/vibroimage layout, linked to the sources' assets, so programs
# run from the build tree find their data by the same rule as installed ones.
include(GNUInstallDirs)

set(VIMG_DATA_SUBDIRS profiles examples gestures)
file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/share/vibroimage)
foreach(sub ${VIMG_DATA_SUBDIRS})
  if(NOT EXISTS ${PROJECT_BINARY_DIR}/share/vibroimage/${sub})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/assets/${sub} ${PROJECT_BINARY_DIR}/share/vibroimage/${sub} SYMBOLIC)
  endif()
endforeach()
# The web player (page, vimg.js, vimg.wasm) is the `web` preset's output (docs/web-building.md); the link may
# dangle until that build has run, and `vimg web` says how to build it.
if(DEFINED VIMG_WEB_ASSETS_DIR AND NOT IS_SYMLINK ${PROJECT_BINARY_DIR}/share/vibroimage/web)
  file(CREATE_LINK ${VIMG_WEB_ASSETS_DIR} ${PROJECT_BINARY_DIR}/share/vibroimage/web SYMBOLIC)
endif()

set(vimg_programs vimg vimg-force vimg-editor vimg-player vimg-probe)
set(vimg_installed_programs "")
foreach(program ${vimg_programs})
  if(TARGET ${program})
    list(APPEND vimg_installed_programs ${program})
  endif()
endforeach()
install(TARGETS ${vimg_installed_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

foreach(sub ${VIMG_DATA_SUBDIRS})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/${sub} DESTINATION ${CMAKE_INSTALL_DATADIR}/vibroimage)
endforeach()
if(DEFINED VIMG_WEB_ASSETS_DIR)
  install(DIRECTORY ${VIMG_WEB_ASSETS_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/vibroimage/web OPTIONAL
          FILES_MATCHING PATTERN "*.html" PATTERN "*.js" PATTERN "*.wasm")
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

if(TARGET vimg-editor)
  install(FILES ${PROJECT_SOURCE_DIR}/packaging/vimg-editor.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES ${PROJECT_SOURCE_DIR}/packaging/vibroimage-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
          RENAME vibroimage.xml)
  install(FILES ${PROJECT_SOURCE_DIR}/packaging/vibroimage.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
endif()
# udev reads /lib/udev/rules.d and /usr/lib/udev/rules.d: relative to the prefix, not the libdir.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/60-vibroimage.rules DESTINATION lib/udev/rules.d)

# Man pages from each program's own --help and --version (help2man), so they cannot drift.
option(VIMG_BUILD_MAN "Make man pages from the programs' --help (needs help2man)" ON)
find_program(HELP2MAN help2man)
if(VIMG_BUILD_MAN AND NOT VIMG_SANITIZE AND HELP2MAN)
  set(vimg_man_pages "")
  set(man_vimg "the headless vibroimage command: validate, convert, render, import, export, inspect")
  set(man_vimg-editor "draw vibrotactile images and play them")
  set(man_vimg-player "play vibrotactile images through an actuator; run the matching test")
  set(man_vimg-probe "explore a volume with the mouse and feel it on a force device")
  set(man_vimg-force "drive a desktop force device over a volume scene; run the location study")
  foreach(program ${vimg_installed_programs})
    set(page ${PROJECT_BINARY_DIR}/man/${program}.1.gz)
    add_custom_command(OUTPUT ${page}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
      COMMAND ${CMAKE_COMMAND} -E env SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
              ${HELP2MAN} --no-info --section=1 "--name=${man_${program}}" --output=${PROJECT_BINARY_DIR}/man/${program}.1
              $<TARGET_FILE:${program}>
      COMMAND gzip -9nf ${PROJECT_BINARY_DIR}/man/${program}.1
      DEPENDS ${program}
      COMMENT "man page of ${program} (help2man)"
      VERBATIM)
    list(APPEND vimg_man_pages ${page})
  endforeach()
  add_custom_target(vimg_man_pages ALL DEPENDS ${vimg_man_pages})
  install(FILES ${vimg_man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
elseif(VIMG_BUILD_MAN AND NOT VIMG_SANITIZE)
  message(STATUS "help2man not found: no man pages (scripts/setup.sh installs it)")
endif()

include(${PROJECT_SOURCE_DIR}/cmake/VimgExport.cmake)

# The Debian package: `cpack -G DEB` in a release build folder gives vibroimage_VERSION_ARCH.deb
# with its dependencies computed from the binaries (dpkg-shlibdeps). scripts/package_check.sh
# installs it with apt, runs it from /usr/bin and removes it again.
set(CPACK_PACKAGE_NAME vibroimage)
set(CPACK_PACKAGE_VENDOR "vibroimage")
set(CPACK_PACKAGE_CONTACT "vibroimage developers <vibroimage@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "vibrotactile images: draw, play and feel pictures on a touchscreen")
set(CPACK_PACKAGE_DESCRIPTION "vibroimage draws vibrotactile images (DOT, LINE and SURFACE primitives on a canvas of
physical size), renders finger motion over them into a drive signal for an LRA (I2C/SPI drivers,
USB HID, audio or a file), drives desktop force devices over volumes, and predicts, runs and
reports matching and location studies. Programs: vimg, vimg-editor, vimg-player, vimg-force,
vimg-probe.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://localhost/vibroimage")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
include(CPack)
