# What `cmake --install` puts where, and in which package (component) each file goes.
#
#   bin/                 executables (RPATH $ORIGIN/../lib: the tree runs from any prefix)
#   lib/                 shared libraries and every transport and estimator plugin, side by side:
#                        the plugin facility looks next to libplumb_plugin.so
#   lib/cmake/plumb/     the CMake package: find_package(plumb) -> plumb::transport, plumb::estimator_api
#   include/plumb/       public headers: transport API, plugin facility, message types, estimator API
#   share/plumb/idl/     the IDL files, for teams that generate their own code
#   share/plumb/config/  DDS configuration files for applications that are not plumb
#   share/doc/plumb/     README and docs/
#
# Components are the Debian packages of cmake/PlumbPackaging.cmake:
#   common  libraries, the `plumb` CLI, IDL, configuration, docs (both computers)
#   cyclonedds, fastdds  one transport plugin each (their package depends on the vendor library)
#   tool    plumb-bridge, plumb-sim (the tool computer, next to the sensors)
#   surface plumb-estimator, plumb-calibrate, plumb-survey, plumb-display (its page is built into the
#           executable: no web files to install), the estimator plugins (the surface computer)
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
install(TARGETS plumb-estimator plumb-calibrate plumb-survey RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT surface)
# The live display, built only where civetweb is installed (components/plumb-display/CMakeLists.txt).
if(TARGET plumb-display)
  install(TARGETS plumb-display RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT surface)
endif()

# Data both computers use: the topic definitions, configuration for stock DDS applications, docs.
file(GLOB plumb_idl_install ${PROJECT_SOURCE_DIR}/idl/*.idl)
install(FILES ${plumb_idl_install} DESTINATION ${PLUMB_INSTALL_DATADIR}/idl COMPONENT common)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/transports/config/ DESTINATION ${PLUMB_INSTALL_DATADIR}/config COMPONENT common)
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
