# What `cmake --install` puts where, and the Debian package `cpack -G DEB` makes of it. The
# programs carry their resources compiled in; beside them go the desktop entry, the file
# types, icons, man pages written from the programs' own help, bash completion, the bundled
# samples and machine descriptions.
include(GNUInstallDirs)

set(ISURFACE_ICON_SIZES 16 22 24 32 48 64)
add_executable(make_icon_sizes ${CMAKE_SOURCE_DIR}/packaging/make_icon_sizes.cpp)
target_link_libraries(make_icon_sizes PRIVATE ${STB_LIBRARY})
set(ISURFACE_ICONS "")
foreach(size ${ISURFACE_ICON_SIZES})
  list(APPEND ISURFACE_ICONS ${CMAKE_BINARY_DIR}/icons/${size}/isurface.png)
endforeach()
add_custom_command(OUTPUT ${ISURFACE_ICONS}
  COMMAND make_icon_sizes ${CMAKE_SOURCE_DIR}/resources/icons/isurface-64.png ${CMAKE_BINARY_DIR}/icons
          ${ISURFACE_ICON_SIZES}
  DEPENDS make_icon_sizes ${CMAKE_SOURCE_DIR}/resources/icons/isurface-64.png
  COMMENT "Icons at ${ISURFACE_ICON_SIZES} pixels")

# Compressed, as Debian installs man pages (-n: no name or time inside, the same bytes each build).
set(ISURFACE_MAN_PAGES ${CMAKE_BINARY_DIR}/man/isurface.1.gz ${CMAKE_BINARY_DIR}/man/isurface-cli.1.gz)
add_custom_command(OUTPUT ${ISURFACE_MAN_PAGES}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
  COMMAND bash ${CMAKE_SOURCE_DIR}/packaging/make_man_page.sh $<TARGET_FILE:isurface> isurface
          ${PROJECT_VERSION} ${CMAKE_BINARY_DIR}/man/isurface.1
  COMMAND bash ${CMAKE_SOURCE_DIR}/packaging/make_man_page.sh $<TARGET_FILE:isurface-cli> isurface-cli
          ${PROJECT_VERSION} ${CMAKE_BINARY_DIR}/man/isurface-cli.1
  COMMAND gzip -9nf ${CMAKE_BINARY_DIR}/man/isurface.1 ${CMAKE_BINARY_DIR}/man/isurface-cli.1
  DEPENDS isurface isurface-cli isurface-cli-all ${CMAKE_SOURCE_DIR}/packaging/make_man_page.sh
  COMMENT "Man pages from the programs' --help")
add_custom_target(isurface_install_files ALL DEPENDS ${ISURFACE_ICONS} ${ISURFACE_MAN_PAGES})

install(TARGETS isurface isurface-cli isurface-cli-all RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${CMAKE_SOURCE_DIR}/packaging/isurface.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${CMAKE_SOURCE_DIR}/packaging/isurface-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
        RENAME isurface.xml)
foreach(size ${ISURFACE_ICON_SIZES})
  install(FILES ${CMAKE_BINARY_DIR}/icons/${size}/isurface.png
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
endforeach()
install(FILES ${ISURFACE_MAN_PAGES} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${CMAKE_SOURCE_DIR}/packaging/isurface-cli.bash-completion
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME isurface-cli)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/samples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/isurface/samples)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/resources/machines/ DESTINATION ${CMAKE_INSTALL_DATADIR}/isurface/machines)
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# cpack -G DEB: the dependencies are the Debian runtime libraries the programs link, as
# dpkg-shlibdeps finds them.
set(CPACK_PACKAGE_NAME isurface)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "NC interpolation quality maps: where a finishing program will leave marks")
set(CPACK_PACKAGE_DESCRIPTION "iSurface reads G-code programs, Biip interpolation dumps and machine traces, \
simulates the NC interpolator, and colours the cutter-location surface by speed, acceleration, jerk, \
adjacent-pass inconsistency and predicted deviation, in a window (isurface) and headless (isurface-cli).")
set(CPACK_PACKAGE_CONTACT "iSurface maintainers <isurface@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-dejavu-core, bash-completion")
set(CPACK_STRIP_FILES ON)
include(CPack)
