# cmake --install (docs/deploy.md): the programs, the public libraries with their headers, the
# CMake package (find_package(gearcoupling)) and pkg-config files, the bundled data, and the
# deployment files. The Debian packages (debian/) are this install under /usr, split.
include(CMakePackageConfigHelpers)

# The physics, the diagnosis above it, gearcoupling::core (an interface target bringing both:
# the one library they were before issue 41), the codec; the client with the service.
set(gc_public_libraries gc_physics gc_diagnosis gc_core gc_codec)
set(gc_programs gearcoupling)
if(GC_BUILD_SERVICE)
  list(APPEND gc_public_libraries gc_client)
  list(APPEND gc_programs gearcoupling-service gearcoupling-monitor gearcoupling-dashboard)
  install(FILES ${PROJECT_BINARY_DIR}/service/gearcoupling-service.bash
    DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME gearcoupling-service)
endif()
install(TARGETS ${gc_programs})
install(FILES ${PROJECT_BINARY_DIR}/clients/cli/gearcoupling.bash
  DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME gearcoupling)
install(TARGETS ${gc_public_libraries} EXPORT gearcoupling-targets)

# Public headers: what the public libraries' headers include, the generated ones too.
set(gc_include_dir ${CMAKE_INSTALL_INCLUDEDIR}/gearcoupling)
install(DIRECTORY core codec diagnosis DESTINATION ${gc_include_dir} FILES_MATCHING PATTERN "*.h")
# The headers' paths before issue 41 (core/diagnosis/, core/validation/, core/synthesis/,
# clients/remote/), each a forward to where the header is now, so that code written against
# gearcoupling::core or the client compiles unchanged.
set(gc_forwards ${PROJECT_BINARY_DIR}/forwarding_headers)
file(GLOB gc_moved_headers RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS
  diagnosis/*.h diagnosis/validation/*.h diagnosis/synthesis/*.h)
if(GC_BUILD_SERVICE)
  list(APPEND gc_moved_headers client/client.h client/client_error.h client/client_types.h
                               client/reply_error.h)
endif()
foreach(header IN LISTS gc_moved_headers)
  string(REGEX REPLACE "^diagnosis/(validation/|synthesis/)" "core/\\1" old "${header}")
  string(REGEX REPLACE "^diagnosis/" "core/diagnosis/" old "${old}")
  string(REGEX REPLACE "^client/" "clients/remote/" old "${old}")
  file(CONFIGURE OUTPUT ${gc_forwards}/${old} CONTENT
    "// ${old} is now ${header} (issue 41): include that.\n#pragma once\n#include \"${header}\"\n")
endforeach()
install(DIRECTORY ${gc_forwards}/ DESTINATION ${gc_include_dir})
install(DIRECTORY ${PROJECT_BINARY_DIR}/idl/ DESTINATION ${gc_include_dir}/idl
  FILES_MATCHING PATTERN "*.pb.h" PATTERN CMakeFiles EXCLUDE)
if(GC_BUILD_SERVICE)
  # What client/client.h includes, and no more: no Cyclone header, nothing idlc wrote.
  install(FILES protocol/batch_types.h protocol/calculation.h protocol/calculation_types.h protocol/dds_error.h
                protocol/jam_angle_result.h protocol/requests.h
    DESTINATION ${gc_include_dir}/protocol)
  install(FILES client/client.h client/client_error.h
                client/client_types.h client/reply_error.h
    DESTINATION ${gc_include_dir}/client)
endif()

# find_package(gearcoupling): the targets, and the packages their headers need.
set(gc_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/gearcoupling)
install(EXPORT gearcoupling-targets NAMESPACE gearcoupling:: DESTINATION ${gc_cmake_dir})
configure_package_config_file(cmake/gearcoupling-config.cmake.in
  ${PROJECT_BINARY_DIR}/gearcoupling-config.cmake INSTALL_DESTINATION ${gc_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/gearcoupling-config-version.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/gearcoupling-config.cmake
  ${PROJECT_BINARY_DIR}/gearcoupling-config-version.cmake DESTINATION ${gc_cmake_dir})

# pkg-config: gearcoupling-physics, -diagnosis, -codec, -client, and -core (no library of its
# own: it requires the physics and the diagnosis). Each names only the pkg-config modules its
# headers need (the client's need no Cyclone: it links libddsc privately). The prefix is written
# at install time (cmake/install_pkg_config.cmake), absolute, as Debian's own .pc files have it:
# `cmake --install --prefix P` gets P, the .deb /usr.
set(gc_pc_physics_requires "eigen3")
set(gc_pc_diagnosis_requires "gearcoupling-physics")
set(gc_pc_core_requires "gearcoupling-physics gearcoupling-diagnosis")
set(gc_pc_codec_requires "gearcoupling-physics protobuf")
set(gc_pc_client_requires "gearcoupling-physics")
set(gc_pc_physics_description "the model of the paper with its effects")
set(gc_pc_diagnosis_description "the model against measurement (validation, synthesis, diagnosis)")
set(gc_pc_core_description "the physics and the diagnosis (gearcoupling-physics, -diagnosis)")
set(gc_pc_codec_description "coupling and model files, results as JSON")
set(gc_pc_client_description "calls to gearcoupling-service over DDS")
set(gc_pc_prefix "@GC_PC_PREFIX@")  # left for install time
set(gc_pc_names "")
foreach(target IN LISTS gc_public_libraries)
  get_target_property(gc_pc_name ${target} EXPORT_NAME)
  set(gc_pc_requires ${gc_pc_${gc_pc_name}_requires})
  set(gc_pc_description ${gc_pc_${gc_pc_name}_description})
  get_target_property(gc_pc_type ${target} TYPE)
  if(gc_pc_type STREQUAL "INTERFACE_LIBRARY")
    set(gc_pc_libs "")
  else()
    set(gc_pc_libs "Libs: -L\${libdir} -lgearcoupling-${gc_pc_name}")
  endif()
  configure_file(cmake/gearcoupling.pc.in
    ${PROJECT_BINARY_DIR}/pkgconfig/gearcoupling-${gc_pc_name}.pc.in @ONLY)
  list(APPEND gc_pc_names gearcoupling-${gc_pc_name})
endforeach()
# Bundled couplings, models and recordings, where codec::bundled_data_dir looks for them.
install(DIRECTORY data/couplings data/models DESTINATION ${CMAKE_INSTALL_DATADIR}/gearcoupling)
install(DIRECTORY data/recordings DESTINATION ${CMAKE_INSTALL_DATADIR}/gearcoupling
  PATTERN make_recordings.sh EXCLUDE)

# Deployment: every Cyclone configuration and the DDS Security tools as examples; the systemd
# unit and the default configuration in etc/gearcoupling (/etc under /usr), written at install
# time because they name the install prefix (cmake/install_system_files.cmake).
set(gc_units "")
if(GC_BUILD_SERVICE)
  set(gc_units gearcoupling-service gearcoupling-monitor gearcoupling-dashboard)
endif()
list(TRANSFORM gc_units APPEND .service OUTPUT_VARIABLE gc_unit_files)
list(TRANSFORM gc_unit_files PREPEND deploy/)
install(FILES deploy/cyclonedds-loopback.xml deploy/cyclonedds-loopback-client.xml
  deploy/cyclonedds-lan.example.xml deploy/cyclonedds-lan-multicast.xml
  deploy/cyclonedds-secure.example.xml deploy/service.conf deploy/monitor.conf
  deploy/dashboard.conf ${gc_unit_files}
  DESTINATION ${CMAKE_INSTALL_DATADIR}/gearcoupling/deploy)
install(PROGRAMS deploy/security/make-security.sh
  DESTINATION ${CMAKE_INSTALL_DATADIR}/gearcoupling/deploy/security)
install(FILES deploy/security/governance.xml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/gearcoupling/deploy/security)
install(CODE "set(GC_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
set(GC_BINARY_DIR \"${PROJECT_BINARY_DIR}\")
set(GC_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
set(GC_DOCDIR \"${CMAKE_INSTALL_DOCDIR}\")
set(GC_UNITS \"${gc_units}\")")
# The files written at install time go to a folder of each install's own (prefix and DESTDIR):
# several installs of one build may run at once (the packaging tests do).
install(CODE [[
string(MD5 GC_INSTALL_KEY "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}")
set(GC_STAGING_DIR "${GC_BINARY_DIR}/install/${GC_INSTALL_KEY}")]])
install(SCRIPT cmake/install_system_files.cmake)
install(CODE "set(GC_PC_NAMES \"${gc_pc_names}\")
set(GC_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")")
install(SCRIPT cmake/install_pkg_config.cmake)

# The README and the pages it links to, in the same layout as the source tree (docs/X.md beside
# README.md), so its links resolve where it is installed; the pages only (not docs/CMakeLists.txt
# or the tutorial's test helper).
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs FILES_MATCHING PATTERN "*.md")
