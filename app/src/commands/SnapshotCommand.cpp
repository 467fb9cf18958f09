#include "commands/SnapshotCommand.h"

#include "commands/ExitCodes.h"

#include "raylab/vis/Display.h"
#include "raylab/vis/SceneView.h"

#include <iostream>
#include <memory>

namespace raylab::app {

Subcommand addSnapshotCommand(CLI::App& cli) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command =
      cli.add_subcommand("snapshot", "Render the window's 3D view offscreen to a PNG file");
  options->add(command, "PNG file to write", "Picture size WIDTHxHEIGHT (default: 300x300)",
               /*outRequired=*/true, /*withAlgorithm=*/false);
  command->get_option("--out")->check(endsIn(".png"));
  return {command, [options](const std::string& topLevelScene) {
            const Scene scene = options->loadScene(topLevelScene);
            checkWritable(options->out);
            vis::requireDisplay();
            const auto [width, height] = options->size.value_or(std::make_pair(300, 300));
            vis::SceneView view(scene);
            view.resetViewCamera(static_cast<double>(width) / height);
            view.renderToPng(options->out, width, height);
            std::cout << options->out << std::endl;
            return int(kExitOk);
          }};
}

}  // namespace raylab::app
