# Install-time part of cmake/install.cmake: the pkg-config files, with the install prefix (known
# only now: `cmake --install --prefix`, or /usr for the .deb) written in as an absolute path.
#   <prefix>/<libdir>/pkgconfig/gearcoupling-{core,codec,client}.pc
# GC_BINARY_DIR, GC_STAGING_DIR, GC_PC_NAMES and GC_LIBDIR come from install(CODE) in
# cmake/install.cmake; the templates are build/pkgconfig/*.pc.in, made from
# cmake/gearcoupling.pc.in at configure time.
cmake_path(SET GC_PC_PREFIX NORMALIZE "${CMAKE_INSTALL_PREFIX}")  # no "..", no "//"
string(REGEX REPLACE "(.)/$" "\\1" GC_PC_PREFIX "${GC_PC_PREFIX}")
foreach(name IN LISTS GC_PC_NAMES)
  configure_file("${GC_BINARY_DIR}/pkgconfig/${name}.pc.in" "${GC_STAGING_DIR}/${name}.pc"
                 @ONLY)
  file(INSTALL "${GC_STAGING_DIR}/${name}.pc" DESTINATION "${GC_PC_PREFIX}/${GC_LIBDIR}/pkgconfig")
endforeach()
