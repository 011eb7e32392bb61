#pragma once
// The GUI's part of a program load: the 3-D scene of the toolpath, built in the program
// session's loading thread (session/programsession.h) as the program's view, and read back
// for rendering. The session's names are the GUI's too (ProgramSession, LoadedProgram,
// ProgramText), so that the window and its tests say them as before.

#include "toolpathscene.h"

#include "session/programsession.h"
#include "session/programtext.h"

#include <cstddef>

namespace frezka::gui {

using session::LoadedProgram;
using session::ProgramMessage;
using session::ProgramSession;
using session::ProgramText;

// The scene as a program view.
struct SceneView : session::ProgramView
{
    explicit SceneView(ToolpathScene s)
        : scene(std::move(s))
    {}
    ToolpathScene scene;
};

// Builds the scene of a toolpath with at most maxSegments segments (vertices for OpenGL when
// glVertices).
session::ViewBuilder sceneBuilder(std::size_t maxSegments, bool glVertices);

// The scene of a loaded program; null when it has none (not loaded, or built without a scene).
std::shared_ptr<const ToolpathScene> sceneOf(const LoadedProgram &program);

} // namespace frezka::gui
