# What `cmake --install` puts where, and the Debian package cpack makes of it:
#   cpack -G DEB  ->  mcpp_<version>_amd64.deb, dependencies from the binaries (dpkg-shlibdeps).
include(GNUInstallDirs)

install(TARGETS mcpp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/resources/mcpp.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/mcpp.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
foreach(size 16 32 48 64 128 256)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/hicolor/mcpp-${size}.png
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps RENAME mcpp.png)
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/samples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/mcpp/samples)
install(DIRECTORY ${PROJECT_BINARY_DIR}/presets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/mcpp/presets)
install(FILES ${PROJECT_SOURCE_DIR}/resources/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The man page is `mcpp --help` and `mcpp --version` put through help2man, when it is installed.
find_program(HELP2MAN help2man)
if(HELP2MAN)
  set(man_page ${PROJECT_BINARY_DIR}/mcpp.1)
  add_custom_command(OUTPUT ${man_page}.gz
    COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen
            ${HELP2MAN} --no-info --section=1 --name "multi-robot coverage path planning over land cover"
            --output=${man_page} $<TARGET_FILE:mcpp>
    COMMAND gzip -9 -n -f ${man_page}
    DEPENDS mcpp
    COMMENT "Writing the man page from mcpp --help")
  add_custom_target(mcpp_man_page ALL DEPENDS ${man_page}.gz)
  install(FILES ${man_page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME mcpp)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "multi-robot coverage path planning over land-cover maps")
set(CPACK_PACKAGE_CONTACT "mcpp developers")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# One paragraph: dpkg shows it wrapped.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Plans how a fleet of robots (ground robots, drones) covers an area whose land cover changes how far a robot sees and how fast it moves. Opens any raster GDAL reads, reads its legend or a preset, divides the area between the robots and plans spanning-tree coverage paths; exports GeoJSON, GeoPackage, KML, GPX and autopilot waypoint files. Runs with a window or headless (mcpp --batch).")
include(CPack)
