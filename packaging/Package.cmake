# The Debian package, made by CPack from the install rules (scripts/dev.sh package runs
# `cpack -G DEB` in the build tree). Runtime dependencies come from dpkg-shlibdeps on the
# installed executables (Debian 12's libqt6core6, libqt6gui6, ...); the Qt platform plugins and
# the X/GL bits the window needs are not linked, so they are named here.
# `cpack` and the install target do not build `all` first (the whole test suite): scripts/dev.sh
# package builds everything before it packages, and a plain `cmake --install` follows a build.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY TRUE)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME frezka)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The Frezka authors")
set(FREZKA_PACKAGE_MAINTAINER "Frezka maintainers <frezka@example.org>"
    CACHE STRING "Maintainer field of the Debian package")
set(CPACK_PACKAGE_CONTACT "${FREZKA_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES TRUE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri, qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "linuxcnc-uspace")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "run CNC mills through GVE hardware interpolators")
# The synopsis line is CPACK_PACKAGE_DESCRIPTION_SUMMARY; this is the long description after it.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Frezka runs CNC mills, engravers and drills through the GVE hardware
interpolators (GVE84, GVE64, GVE64 PHANTOM, GVE114) over RS232, and moves
programs to and from ANC/K51 grinding controls. It reads G-code in the
LinuxCNC dialect, plans the motion within the machine's limits and streams it
to the unit; a built-in emulator of the units lets everything run without a
machine.
.
The package holds the desktop application (frezka), the headless front end
(frezka-cli), and the emulators gve-emu and k51-emu.")
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "")
# Only what the install rules name: no source package, no build tree.
set(CPACK_SOURCE_GENERATOR "")
include(CPack)
