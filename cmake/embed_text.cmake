# gc_embed_text(TARGET FILE HEADER CONSTANT): the text of FILE (in the current source folder)
# compiled into TARGET as `inline constexpr std::string_view CONSTANT` in the generated header
# HEADER (in the current binary folder, on TARGET's private include path). CMake configures again
# when FILE changes. Used for the validation report's script and the dashboard's page.
function(gc_embed_text target file header constant)
  file(READ ${CMAKE_CURRENT_SOURCE_DIR}/${file} GC_EMBEDDED_TEXT)
  file(RELATIVE_PATH source ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/${file})
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${header}.in
    "// Generated from ${source} by CMake (cmake/embed_text.cmake).\n#pragma once\n#include <string_view>\n"
    "inline constexpr std::string_view ${constant} = R\"gctext(@GC_EMBEDDED_TEXT@)gctext\";\n")
  configure_file(${CMAKE_CURRENT_BINARY_DIR}/${header}.in ${CMAKE_CURRENT_BINARY_DIR}/${header} @ONLY)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
endfunction()
