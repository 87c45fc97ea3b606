# Debian packages from the build tree: `cpack -G DEB` (run in the build folder) writes one .deb per
# component of cmake/PlumbInstall.cmake, all installing under /opt/plumb:
#
#   plumb-common                libraries, `plumb` CLI, IDL, configuration files, docs
#   plumb-transport-cyclonedds  Cyclone DDS transport plugin   (depends on libddsc0debian)
#   plumb-transport-fastdds     Fast DDS transport plugin      (depends on libfastrtps2.9, libfastcdr1)
#   plumb-tool                  tool computer: plumb-bridge, plumb-sim, the plumb-bridge@ unit
#   plumb-surface               surface computer: plumb-estimator, plumb-calibrate, plumb-survey,
#                               plumb-display (depends on libcivetweb1), plumb-wits, estimator
#                               plugins, their units
#   (tool and surface make the plumb system user in postinst, and /etc/plumb's environment files)
#   plumb-dev                   headers, CMake package, examples
#
# The vendor dependencies come from dpkg-shlibdeps (what the binaries really link), plumb's own
# from the lines below. A vendor left out at build time (PLUMB_WITH_*=OFF) has no package and no
# dependency on it.
#
# /opt/plumb, not /usr: plumb's libraries are private (no soname versioning, no -dev split per
# library), and a self-contained tree is what the RPATH ($ORIGIN/../lib) and the plugin search
# (next to libplumb_plugin.so) expect. Field engineers add /opt/plumb/bin to PATH.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME plumb)
set(CPACK_PACKAGE_VENDOR "plumb")
set(CPACK_PACKAGE_CONTACT "plumb maintainers <plumb@localhost>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "drilling-tool attitude from accelerometers, magnetometers and gyros over DDS")
set(CPACK_PACKAGING_INSTALL_PREFIX /opt/plumb)
set(CPACK_STRIP_FILES ON)  # the build carries debug information; the packages do not
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# plumb's own libraries are found in the build tree; which package holds them is said below.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PROJECT_BINARY_DIR}/lib)

get_property(plumb_packaged_vendors GLOBAL PROPERTY PLUMB_TRANSPORT_PLUGINS)
set(CPACK_COMPONENTS_ALL common tool surface dev ${plumb_packaged_vendors})

set(plumb_exact "(= ${PROJECT_VERSION})")
set(plumb_any_transport "")
foreach(vendor ${plumb_packaged_vendors})
  string(TOUPPER ${vendor} upper)
  set(CPACK_DEBIAN_${upper}_PACKAGE_NAME plumb-transport-${vendor})
  set(CPACK_DEBIAN_${upper}_PACKAGE_DEPENDS "plumb-common ${plumb_exact}")
  set(CPACK_COMPONENT_${upper}_DESCRIPTION "plumb's ${vendor} transport plugin (DDS vendor chosen at run time with --transport ${vendor})")
  if(plumb_any_transport)
    string(APPEND plumb_any_transport " | ")
  endif()
  string(APPEND plumb_any_transport "plumb-transport-${vendor} ${plumb_exact}")
endforeach()

set(CPACK_DEBIAN_COMMON_PACKAGE_NAME plumb-common)
set(CPACK_COMPONENT_COMMON_DESCRIPTION "plumb libraries, the plumb command-line tool, IDL, DDS configuration files, docs")
# `plumb security create-keystore/create-identity/create-permissions` run the openssl program; the
# rest of plumb does not, so it is recommended rather than required (without it those commands say
# to install it).
set(CPACK_DEBIAN_COMMON_PACKAGE_RECOMMENDS "openssl, python3-matplotlib")
set(CPACK_DEBIAN_TOOL_PACKAGE_NAME plumb-tool)
set(CPACK_DEBIAN_TOOL_PACKAGE_DEPENDS "plumb-common ${plumb_exact}, ${plumb_any_transport}")
set(CPACK_COMPONENT_TOOL_DESCRIPTION "plumb for the tool computer: hardware bridge (plumb-bridge) and simulated platform (plumb-sim)")
set(CPACK_DEBIAN_SURFACE_PACKAGE_NAME plumb-surface)
set(CPACK_DEBIAN_SURFACE_PACKAGE_DEPENDS "plumb-common ${plumb_exact}, ${plumb_any_transport}")
set(CPACK_COMPONENT_SURFACE_DESCRIPTION "plumb for the surface computer: estimator host, estimator plugins, calibration, survey, live display")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME plumb-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "plumb-common ${plumb_exact}, libeigen3-dev")
set(CPACK_COMPONENT_DEV_DESCRIPTION "plumb headers and CMake package (find_package(plumb)), examples")
# The systemd units' user (adduser in postinst), their environment files, stopping them on removal.
foreach(package tool surface)
  set(plumb_units "${plumb_${package}_stop_units}")
  file(READ ${PROJECT_SOURCE_DIR}/deploy/debian/prerm.in prerm)
  string(REPLACE "@plumb_units@" "${plumb_units}" prerm "${prerm}")
  file(WRITE ${PROJECT_BINARY_DIR}/debian/${package}/prerm "${prerm}")
  file(COPY ${PROJECT_SOURCE_DIR}/deploy/debian/postinst ${PROJECT_SOURCE_DIR}/deploy/debian/postrm
       DESTINATION ${PROJECT_BINARY_DIR}/debian/${package})
  file(CHMOD ${PROJECT_BINARY_DIR}/debian/${package}/prerm PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE
       GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  string(TOUPPER ${package} upper)
  set(CPACK_DEBIAN_${upper}_PACKAGE_CONTROL_EXTRA
      "${PROJECT_BINARY_DIR}/debian/${package}/postinst;${PROJECT_BINARY_DIR}/debian/${package}/prerm;${PROJECT_BINARY_DIR}/debian/${package}/postrm")
  string(APPEND CPACK_DEBIAN_${upper}_PACKAGE_DEPENDS ", adduser")
endforeach()
# Both transports are wanted where both were built; either one is enough.
string(REPLACE " | " ", " CPACK_DEBIAN_TOOL_PACKAGE_RECOMMENDS "${plumb_any_transport}")
set(CPACK_DEBIAN_SURFACE_PACKAGE_RECOMMENDS "${CPACK_DEBIAN_TOOL_PACKAGE_RECOMMENDS}")

include(CPack)
