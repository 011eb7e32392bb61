// The program's scene as the session's program view. See programview.h.

#include "programview.h"

namespace frezka::gui {

session::ViewBuilder sceneBuilder(std::size_t maxSegments, bool glVertices)
{
    return [maxSegments, glVertices](const gcode::Toolpath &toolpath,
                                     const std::function<void(double)> &progress,
                                     const std::atomic_bool *cancel) {
        SceneOptions options;
        options.maxSegments = maxSegments;
        options.glVertices = glVertices;
        return std::make_shared<const SceneView>(buildScene(
            toolpath, options,
            [&](std::size_t done, std::size_t total) {
                progress(double(done) / double(std::max<std::size_t>(1, total)));
            },
            cancel));
    };
}

std::shared_ptr<const ToolpathScene> sceneOf(const LoadedProgram &program)
{
    const auto view = std::dynamic_pointer_cast<const SceneView>(program.view);
    if (!view)
        return nullptr;
    // Shares the view's ownership: the scene lives as long as anybody renders it.
    return std::shared_ptr<const ToolpathScene>(view, &view->scene);
}

} // namespace frezka::gui
