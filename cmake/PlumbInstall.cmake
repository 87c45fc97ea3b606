# What `cmake --install` puts where, and in which package (component) each file goes.
#
#   bin/                 executables (RPATH $ORIGIN/../lib: the tree runs from any prefix)
#   lib/                 shared libraries and every transport and estimator plugin, side by side:
#                        the plugin facility looks next to libplumb_plugin.so
#   lib/cmake/plumb/     the CMake package: find_package(plumb) -> plumb::transport, plumb::estimator_api
#   include/plumb/       public headers: transport API, plugin facility, message types, estimator API
#   share/plumb/idl/     the IDL files, for teams that generate their own code
#   share/plumb/config/  DDS configuration files for applications that are not plumb
#   share/plumb/params/  parameters files (--params-file), share/plumb/launch/ launch files
#   share/plumb/foxglove/ the Foxglove layout for plumb-display's Foxglove WebSocket server
#   share/plumb/systemd/env/  templates of /etc/plumb's environment files (the packages' postinst
#                        copies the missing ones there)
#   /lib/systemd/system/ the systemd units, when installing to /opt/plumb (the packages); into any
#                        other prefix they go to PREFIX/lib/systemd/system, for inspection only
#   share/doc/plumb/     README and docs/
#
# Components are the Debian packages of cmake/PlumbPackaging.cmake:
#   common  libraries, the `plumb` CLI, IDL, configuration, docs (both computers)
#   cyclonedds, fastdds  one transport plugin each (their package depends on the vendor library)
#   tool    plumb-bridge, plumb-sim (the tool computer, next to the sensors)
#   surface plumb-estimator, plumb-calibrate, plumb-survey, plumb-display (its page is built into the
#           executable: no web files to install), plumb-wits and plumb-wits-send, the estimator
#           plugins (the surface computer)
#   dev     headers, CMake package, example sources and programs (other teams)
include(CMakePackageConfigHelpers)

set(PLUMB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/plumb)
set(PLUMB_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/plumb)

# Libraries every executable needs; the exported ones carry the public API.
set(plumb_exported_libraries plumb_core plumb_plugin plumb_topics plumb_transport plumb_estimator_api)
install(TARGETS ${plumb_exported_libraries} EXPORT plumbTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT common
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS plumb_csv plumb_mcap plumb_survey plumb_survey_file plumb_sim plumb_estimators_loader plumb_compare
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT common)
install(TARGETS plumb RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT common)
# plumb survey --plot and plumb compare --plots run it from plumb's own folder.
install(PROGRAMS ${PROJECT_SOURCE_DIR}/components/plumb-plot/plumb-plot DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT common)

get_property(plumb_transport_plugins GLOBAL PROPERTY PLUMB_TRANSPORT_PLUGINS)
foreach(vendor ${plumb_transport_plugins})
  install(TARGETS plumb_transport_${vendor} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${vendor})
endforeach()

install(TARGETS plumb-bridge plumb-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tool)

get_property(plumb_estimator_plugins GLOBAL PROPERTY PLUMB_ESTIMATOR_PLUGINS)
foreach(plugin ${plumb_estimator_plugins})
  install(TARGETS plumb_estimator_${plugin} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT surface)
endforeach()
install(TARGETS plumb_calibration plumb_station_list LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT surface)
install(TARGETS plumb-estimator plumb-calibrate plumb-survey plumb-wits plumb-wits-send
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT surface)
# The live display, built only where civetweb is installed (components/plumb-display/CMakeLists.txt).
if(TARGET plumb-display)
  install(TARGETS plumb-display RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT surface)
  # The Foxglove layout for its Foxglove WebSocket server (examples/foxglove/README.md).
  install(FILES ${PROJECT_SOURCE_DIR}/examples/foxglove/plumb-layout.json DESTINATION ${PLUMB_INSTALL_DATADIR}/foxglove
          COMPONENT surface)
endif()

# Data both computers use: the topic definitions, configuration for stock DDS applications, docs.
file(GLOB plumb_idl_install ${PROJECT_SOURCE_DIR}/idl/*.idl)
install(FILES ${plumb_idl_install} DESTINATION ${PLUMB_INSTALL_DATADIR}/idl COMPONENT common)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/transports/config/ DESTINATION ${PLUMB_INSTALL_DATADIR}/config COMPONENT common)
# Parameters and launch files; the build tree has them in the same place (build/share/plumb/...),
# so that the README's commands read the same files from a build as from an installation.
foreach(kind params launch)
  file(GLOB plumb_${kind}_install CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/deploy/${kind}/*.yaml)
  install(FILES ${plumb_${kind}_install} DESTINATION ${PLUMB_INSTALL_DATADIR}/${kind} COMPONENT common)
  foreach(file ${plumb_${kind}_install})
    get_filename_component(name ${file} NAME)
    configure_file(${file} ${PROJECT_BINARY_DIR}/share/plumb/${kind}/${name} COPYONLY)
  endforeach()
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT common)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT common
        FILES_MATCHING PATTERN "*.md" PATTERN "*.xml")

# Public headers: the transport API with the message types it passes, the plugin facility, the
# estimator API with the vocabulary it passes. Generated ones (ABI hashes, message types) included.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/transports/include/plumb ${PROJECT_BINARY_DIR}/transports/include/plumb
                  ${PROJECT_BINARY_DIR}/idl/topics/plumb ${PROJECT_SOURCE_DIR}/idl/generate/runtime/plumb
                  ${PROJECT_SOURCE_DIR}/estimators/plugins/api/include/plumb ${PROJECT_BINARY_DIR}/estimators/plugins/api/include/plumb
                  ${PROJECT_SOURCE_DIR}/estimators/core/include/plumb
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev FILES_MATCHING PATTERN "*.hpp")
# The plugin facility's folder holds the estimator loader too, which is not public: its header alone.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/estimators/plugins/loader/include/plumb/plugin
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/plumb COMPONENT dev FILES_MATCHING PATTERN "*.hpp")

# The CMake package.
install(EXPORT plumbTargets NAMESPACE plumb:: DESTINATION ${PLUMB_INSTALL_CMAKEDIR} COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/plumbConfig.cmake.in
  ${PROJECT_BINARY_DIR}/plumbConfig.cmake INSTALL_DESTINATION ${PLUMB_INSTALL_CMAKEDIR}
  PATH_VARS PLUMB_INSTALL_DATADIR CMAKE_INSTALL_LIBDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/plumbConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/plumbConfig.cmake ${PROJECT_BINARY_DIR}/plumbConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/plumbPlugins.cmake
        DESTINATION ${PLUMB_INSTALL_CMAKEDIR} COMPONENT dev)

# The examples other teams copy: their sources (they build against this package) and programs.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples COMPONENT dev)
foreach(example plumb-example-publisher plumb-example-subscriber plumb-c-attitude-listener)
  if(TARGET ${example})
    install(TARGETS ${example} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT dev)
  endif()
endforeach()

# systemd units and the templates of their environment files, per computer. The units name
# /opt/plumb/bin: they belong where the packages install.
set(plumb_env ${PROJECT_SOURCE_DIR}/deploy/systemd/env)
set(plumb_units ${PROJECT_SOURCE_DIR}/deploy/systemd)
install(FILES ${plumb_env}/plumb.env DESTINATION ${PLUMB_INSTALL_DATADIR}/systemd/env COMPONENT common)
install(FILES ${plumb_env}/bridge-board.env DESTINATION ${PLUMB_INSTALL_DATADIR}/systemd/env COMPONENT tool)
set(plumb_surface_units plumb-estimator.service plumb-survey.service plumb-wits.service)
set(plumb_surface_env estimator.env survey.env wits.env)
if(TARGET plumb-display)
  list(APPEND plumb_surface_units plumb-display.service)
  list(APPEND plumb_surface_env display.env)
endif()
list(TRANSFORM plumb_surface_env PREPEND ${plumb_env}/)
install(FILES ${plumb_surface_env} DESTINATION ${PLUMB_INSTALL_DATADIR}/systemd/env COMPONENT surface)
# plumb_install_units(COMPONENT UNIT...): decided at install time, since `cmake --install --prefix
# DIR` and cpack run the same script (cpack with the prefix /opt/plumb and DESTDIR set).
function(plumb_install_units component)
  list(TRANSFORM ARGN PREPEND ${plumb_units}/ OUTPUT_VARIABLE files)
  install(CODE "
    if(CMAKE_INSTALL_PREFIX STREQUAL \"/opt/plumb\")
      set(plumb_unit_dir /lib/systemd/system)
    else()
      set(plumb_unit_dir \"\${CMAKE_INSTALL_PREFIX}/lib/systemd/system\")
    endif()
    file(INSTALL DESTINATION \"\${plumb_unit_dir}\" TYPE FILE FILES ${files})
  " COMPONENT ${component})
endfunction()
plumb_install_units(tool plumb-bridge@.service)
plumb_install_units(surface ${plumb_surface_units})
# For the packages' prerm (cmake/PlumbPackaging.cmake): what each one stops on removal.
set(plumb_tool_stop_units "'plumb-bridge@*.service'")  # quoted: a pattern for systemctl, not the shell
string(REPLACE ";" " " plumb_surface_stop_units "${plumb_surface_units}")
