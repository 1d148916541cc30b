# Install-time part of cmake/install.cmake: the systemd unit and the default configuration name
# the install prefix, which is known only now (`cmake --install --prefix`, or /usr for the .deb).
#   <prefix>/lib/systemd/system/gearcoupling-service.service
#   /etc/gearcoupling/{service.conf,cyclonedds.xml} under /usr, else <prefix>/etc/gearcoupling/
# deploy/gearcoupling-service.service is the unit as the .deb installs it (/usr/bin, /etc); other
# prefixes get their own paths written in.
if(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(etc_dir "/etc/gearcoupling")
else()
  set(etc_dir "${CMAKE_INSTALL_PREFIX}/etc/gearcoupling")
endif()

file(READ "${GC_SOURCE_DIR}/deploy/gearcoupling-service.service" unit)
string(REPLACE "/usr/bin/" "${CMAKE_INSTALL_PREFIX}/${GC_BINDIR}/" unit "${unit}")
string(REPLACE "/usr/share/doc/gearcoupling/" "${CMAKE_INSTALL_PREFIX}/${GC_DOCDIR}/" unit "${unit}")
string(REPLACE "/etc/gearcoupling/" "${etc_dir}/" unit "${unit}")
file(WRITE "${GC_BINARY_DIR}/install/gearcoupling-service.service" "${unit}")
file(INSTALL "${GC_BINARY_DIR}/install/gearcoupling-service.service"
  DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/systemd/system")

# The configuration is the administrator's once written: an install does not overwrite it (the
# .deb marks it as conffiles, so dpkg asks).
foreach(source_and_name "service.conf;service.conf" "cyclonedds-loopback.xml;cyclonedds.xml")
  list(GET source_and_name 0 source)
  list(GET source_and_name 1 name)
  if(EXISTS "$ENV{DESTDIR}${etc_dir}/${name}")
    message(STATUS "Kept: $ENV{DESTDIR}${etc_dir}/${name}")
  else()
    file(INSTALL "${GC_SOURCE_DIR}/deploy/${source}" DESTINATION "${etc_dir}" RENAME "${name}")
  endif()
endforeach()
