#pragma once
// The version of this build: CMake's project version and, when built from git, the commit's
// description ("0.1.0 (git v0.1.0-3-gabc1234)"). Defined in a file that CMake generates at
// configure time (cmake/FrezkaVersion.cmake), so that a new commit recompiles that one file.

namespace frezka::app {

const char *versionString();

} // namespace frezka::app
