# Install-time part of cmake/install.cmake: the systemd units and the default configuration name
# the install prefix, which is known only now (`cmake --install --prefix`, or /usr for the .deb).
#   <prefix>/lib/systemd/system/gearcoupling-{service,monitor,dashboard}.service
#   /etc/gearcoupling/{service,monitor,dashboard}.conf and cyclonedds.xml under /usr, else
#   <prefix>/etc/gearcoupling/
# deploy/gearcoupling-*.service are the units as the .deb installs them (/usr/bin, /etc); other
# prefixes get their own paths written in. GC_UNITS (the programs with a unit) and GC_STAGING_DIR
# come from install(CODE) in cmake/install.cmake.
if(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(etc_dir "/etc/gearcoupling")
else()
  set(etc_dir "${CMAKE_INSTALL_PREFIX}/etc/gearcoupling")
endif()

foreach(program IN LISTS GC_UNITS)
  file(READ "${GC_SOURCE_DIR}/deploy/${program}.service" unit)
  string(REPLACE "/usr/bin/" "${CMAKE_INSTALL_PREFIX}/${GC_BINDIR}/" unit "${unit}")
  string(REPLACE "/usr/share/doc/gearcoupling/" "${CMAKE_INSTALL_PREFIX}/${GC_DOCDIR}/" unit "${unit}")
  string(REPLACE "/etc/gearcoupling/" "${etc_dir}/" unit "${unit}")
  file(WRITE "${GC_STAGING_DIR}/${program}.service" "${unit}")
  file(INSTALL "${GC_STAGING_DIR}/${program}.service"
    DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/systemd/system")
endforeach()

# The configuration is the administrator's once written: an install does not overwrite it (the
# .deb's files in /etc are conffiles, so dpkg asks). Each file is deploy/<name>, but
# cyclonedds.xml, which is deploy/cyclonedds-loopback.xml: loopback only until replaced.
set(names service.conf cyclonedds.xml)
foreach(program monitor dashboard)
  list(FIND GC_UNITS "gearcoupling-${program}" unit)  # install scripts run with old policies: no IN_LIST
  if(unit GREATER -1)
    list(APPEND names ${program}.conf)
  endif()
endforeach()
foreach(name IN LISTS names)
  set(source "${name}")
  if(name STREQUAL "cyclonedds.xml")
    set(source "cyclonedds-loopback.xml")
  endif()
  if(EXISTS "$ENV{DESTDIR}${etc_dir}/${name}")
    message(STATUS "Kept: $ENV{DESTDIR}${etc_dir}/${name}")
  else()
    file(INSTALL "${GC_SOURCE_DIR}/deploy/${source}" DESTINATION "${etc_dir}" RENAME "${name}")
  endif()
endforeach()
