# gc_public_library(<target> <name>): makes <target> the installed, exported shared library
# libgearcoupling-<name>.so.<major> (SONAME), known as gearcoupling::<name> both to a project
# that finds the installed package and to one that adds this tree with add_subdirectory.
# Headers are included as "core/jam_angle.h", "client/client.h", ...: from the source
# tree when building, from include/gearcoupling once installed.
function(gc_public_library target name)
  add_library(gearcoupling::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES
    OUTPUT_NAME gearcoupling-${name}
    EXPORT_NAME ${name}
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}
    INSTALL_RPATH "$ORIGIN")
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/gearcoupling>)
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()
