# app_install: installs the build into a scratch prefix with `cmake --install`, as a user or a
# packager would, and checks that Marbler lands in place and runs from there:
#  - bin/marbler, its modules in lib/marbler, the launcher, the icon and the MIME type;
#  - the installed marbler finds its modules in the install tree (`marbler doctor` names the
#    files it uses), not in the build tree it also knows of;
#  - the launcher opens genome files (Exec=marbler %F) of the MIME type the MIME file defines;
#  - desktop-file-validate and update-mime-database accept the files, where they are installed.
#
# cmake -DBUILD_DIR=... -DPREFIX=... -P InstallTest.cmake

foreach(var BUILD_DIR PREFIX)
  if(NOT ${var})
    message(FATAL_ERROR "InstallTest.cmake needs -D${var}=...")
  endif()
endforeach()

file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}${err}")
endif()

set(desktop "${PREFIX}/share/applications/marbler.desktop")
set(mime "${PREFIX}/share/mime/packages/marbler.xml")
set(icon "${PREFIX}/share/icons/hicolor/scalable/apps/marbler.svg")
foreach(file "${PREFIX}/bin/marbler" "${PREFIX}/lib/marbler/marbler-window.so"
             "${PREFIX}/lib/marbler/marbler-imageio.so"
             "${PREFIX}/lib/marbler/marbler-video.so" "${desktop}" "${mime}" "${icon}")
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "cmake --install did not install ${file}")
  endif()
endforeach()

# Run from the install tree with nothing pointing elsewhere and no display (doctor then skips
# OpenGL): every module must come from PREFIX/lib/marbler.
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=MARBLER_MODULE_DIR --unset=DISPLAY
                        --unset=WAYLAND_DISPLAY --unset=QT_QPA_PLATFORM "${PREFIX}/bin/marbler" --version
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "^marbler [0-9]")
  message(FATAL_ERROR "the installed marbler --version failed (${rc}):\n${out}${err}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=MARBLER_MODULE_DIR --unset=DISPLAY
                        --unset=WAYLAND_DISPLAY --unset=QT_QPA_PLATFORM "${PREFIX}/bin/marbler" doctor
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed marbler doctor failed (${rc}):\n${out}${err}")
endif()
foreach(module marbler-imageio.so marbler-window.so)
  string(FIND "${out}" "(${PREFIX}/lib/marbler/${module})" at)
  if(at LESS 0)
    message(FATAL_ERROR "the installed marbler does not use ${PREFIX}/lib/marbler/${module}:\n${out}${err}")
  endif()
endforeach()

# The launcher and the MIME type name the same type, and the type is for *.marble.json.
file(READ "${desktop}" entry)
file(READ "${mime}" types)
if(NOT entry MATCHES "\nExec=marbler %F\n")
  message(FATAL_ERROR "${desktop}: Exec must be 'marbler %F' (the window opens the files given)")
endif()
if(NOT entry MATCHES "\nIcon=marbler\n")
  message(FATAL_ERROR "${desktop}: Icon must be 'marbler', the installed icon's name")
endif()
if(NOT entry MATCHES "\nCategories=[^\n]*Graphics;")
  message(FATAL_ERROR "${desktop}: Categories must include Graphics")
endif()
if(NOT entry MATCHES "\nMimeType=([^\n]*)\n")
  message(FATAL_ERROR "${desktop} has no MimeType line")
endif()
string(REGEX MATCHALL "[^;]+" launcherTypes "${CMAKE_MATCH_1}")
string(REGEX MATCHALL "<mime-type type=\"[^\"]+\"" defined "${types}")
string(REGEX REPLACE "<mime-type type=\"([^\"]+)\"" "\\1" defined "${defined}")
if(NOT launcherTypes STREQUAL defined)
  message(FATAL_ERROR "the launcher's MimeType (${launcherTypes}) is not the type ${mime} defines (${defined})")
endif()
if(NOT types MATCHES "<glob pattern=\"\\*\\.marble\\.json\"" OR NOT types MATCHES "<sub-class-of type=\"application/json\"/>")
  message(FATAL_ERROR "${mime} must match *.marble.json and be a kind of application/json")
endif()

# The freedesktop.org tools, where this machine has them, accept the files.
find_program(DESKTOP_FILE_VALIDATE desktop-file-validate)
if(DESKTOP_FILE_VALIDATE)
  execute_process(COMMAND "${DESKTOP_FILE_VALIDATE}" "${desktop}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
    message(FATAL_ERROR "desktop-file-validate rejects ${desktop}:\n${out}${err}")
  endif()
else()
  message(STATUS "desktop-file-validate not found: the launcher is checked by the rules above only")
endif()
find_program(UPDATE_MIME_DATABASE update-mime-database)
if(UPDATE_MIME_DATABASE)
  execute_process(COMMAND "${UPDATE_MIME_DATABASE}" "${PREFIX}/share/mime" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${PREFIX}/share/mime/application/x-marbler-genome.xml")
    message(FATAL_ERROR "update-mime-database does not take ${mime} (${rc}):\n${out}${err}")
  endif()
endif()
file(REMOVE_RECURSE "${PREFIX}")
