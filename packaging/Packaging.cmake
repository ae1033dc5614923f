# Marbler as a Debian package (docs/packaging.md): what an installed Marbler has besides the
# executable, its modules and the desktop files (app/desktop), and CPack's DEB settings.
# `./dev.sh package` configures a Release tree with CMAKE_INSTALL_PREFIX=/usr and runs cpack;
# `./dev.sh test` packs its own build tree the same way (the prefix is CPack's, below).
#
# The executable finds its modules in ../lib/marbler beside itself (render/image/src/Modules.cpp),
# so the package keeps that layout: /usr/bin/marbler and /usr/lib/marbler/*.so, a private folder
# of the package (Debian policy 10.2), no RPATH and no ld.so configuration needed.

set(MARBLER_PACKAGING_DIR ${CMAKE_CURRENT_LIST_DIR})

# The manual page, made from the built executable's own help (`marbler --help` and each verb's
# `--help`) by packaging/make-manpage.sh, so the two cannot drift (tests/packaging checks it).
set(MARBLER_MANPAGE ${PROJECT_BINARY_DIR}/packaging/marbler.1)
add_custom_command(
  OUTPUT ${MARBLER_MANPAGE} ${MARBLER_MANPAGE}.gz
  COMMAND bash ${MARBLER_PACKAGING_DIR}/make-manpage.sh $<TARGET_FILE:marbler> ${PROJECT_VERSION}
          ${MARBLER_MANPAGE}
  # -n: no name or time stamp in the gzip header, so the package is reproducible (lintian).
  COMMAND gzip -9nf -k ${MARBLER_MANPAGE}
  DEPENDS marbler ${MARBLER_PACKAGING_DIR}/make-manpage.sh
  COMMENT "Writing the manual page marbler.1 from marbler --help"
  VERBATIM)
# Marbler is its own upstream (a native package, no Debian revision), so its changelog is
# changelog.gz in Debian's format.
set(MARBLER_CHANGELOG ${PROJECT_BINARY_DIR}/packaging/changelog.gz)
add_custom_command(
  OUTPUT ${MARBLER_CHANGELOG}
  COMMAND gzip -9n -c ${MARBLER_PACKAGING_DIR}/changelog.Debian > ${MARBLER_CHANGELOG}
  DEPENDS ${MARBLER_PACKAGING_DIR}/changelog.Debian
  VERBATIM)
add_custom_target(marbler_package_files ALL DEPENDS ${MARBLER_MANPAGE}.gz ${MARBLER_CHANGELOG})

install(FILES ${MARBLER_MANPAGE}.gz DESTINATION share/man/man1)
install(FILES ${MARBLER_PACKAGING_DIR}/marbler.bash-completion
        DESTINATION share/bash-completion/completions RENAME marbler)
install(FILES ${MARBLER_PACKAGING_DIR}/copyright ${MARBLER_CHANGELOG} DESTINATION share/doc/marbler)
file(GLOB MARBLER_EXAMPLES ${PROJECT_SOURCE_DIR}/tests/data/examples/*.marble.json)
install(FILES ${MARBLER_EXAMPLES} DESTINATION share/doc/marbler/examples)
if(MARBLER_BUILD_GUI)
  # AppStream: what software centres show (the window is what they offer, so it comes with it).
  install(FILES ${MARBLER_PACKAGING_DIR}/io.github.marbler.Marbler.metainfo.xml DESTINATION share/metainfo)
endif()

# CPack: one binary package, marbler_VERSION_amd64.deb.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME marbler)
set(CPACK_PACKAGE_VENDOR "Marbler")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
# Files 0644 and folders 0755 whatever the builder's umask (lintian: non-standard-dir-perm).
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "Marbler Dev <dev@marbler.invalid>")
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/marbler/marbler")
# The runtime libraries come from the binaries (dpkg-shlibdeps), so no -dev package is pulled in.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt's platform plugins (the window's connection to X11 and Wayland) are loaded, not linked, so
# shlibdeps cannot see them, and libqt6gui6 only recommends them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
# The window renders with OpenGL through whatever driver the machine has; Mesa's is the fallback.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "workbench for breeding mathematical marbling designs")
# The long description, after the summary line; CPack indents it and marks the empty line.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Marbler makes marbled designs, flat like paper or solid like carved stone,
from closed-form, area-preserving operations: ink drops, tine lines, combs,
waves, circular strokes and vortices. A design is a short list of these
operations (its genome), so it renders sharply at any size.

The workbench breeds designs nine at a time; the editor refines one by hand.
The marbler command renders, breeds and converts designs without a display:
raster images, layered SVG for print, textures on 3D objects, animations.")
include(CPack)
