# cpack (in the build folder) makes gearcoupling_<version>_<arch>.deb: cmake/install.cmake's
# install under /usr, the configuration in /etc/gearcoupling as conffiles, the system user made by
# deploy/debian/postinst, the dependencies found by dpkg-shlibdeps (docs/deploy.md).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gearcoupling)
set(CPACK_PACKAGE_VENDOR "gearcoupling")
set(CPACK_PACKAGE_CONTACT "gearcoupling maintainers <gearcoupling@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "wind-turbine gear-coupling model: calculation service over DDS, CLI, libraries")
set(CPACK_PACKAGE_DESCRIPTION
  "The analytic gear-coupling model of Guo et al. (NREL): tooth contact, jam angle, induced
moments, restoring torque and friction. gearcoupling-service answers over Cyclone DDS; the
gearcoupling CLI runs in process or on the service; libgearcoupling-core, -codec and -client with
their headers, CMake package and pkg-config files; the bundled couplings and models.")
# The install runs with prefix /usr into a staging DESTDIR, so that install_system_files.cmake
# puts the configuration in /etc.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "adduser")
# Building against the headers needs their -dev packages; validate --html inlines Chart.js.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libeigen3-dev, libprotobuf-dev, cyclonedds-dev")
# The Python module (usr/lib/python3/dist-packages/gearcoupling) imports numpy; pandas for
# DataFrames, matplotlib for the examples.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libjs-chart.js, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "${CPACK_DEBIAN_PACKAGE_SUGGESTS}, python3-pandas, python3-matplotlib")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
  ${PROJECT_SOURCE_DIR}/deploy/debian/conffiles
  ${PROJECT_SOURCE_DIR}/deploy/debian/postinst
  ${PROJECT_SOURCE_DIR}/deploy/debian/prerm
  ${PROJECT_SOURCE_DIR}/deploy/debian/postrm
  ${PROJECT_SOURCE_DIR}/deploy/debian/triggers)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
