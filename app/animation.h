// POV-Ray's animation: the frames an animation's options ask for, each frame's clock values and image name.
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "app/options.h"
#include "parser/parse.h"

namespace wardray::app {

/// One image to render: its frame number (0 for a still), the values the scene reads, its file.
struct Frame {
    int number = 0;
    parser::ParseOptions::FrameClock clock;
    std::filesystem::path output;
};

/// The frames to render, in order, with their outputs named from `output` ("scene.png" gives scene01.png ...
/// when the last frame has two digits). A still is one frame with `output` unchanged. The message says why
/// there is no frame ("the final frame 2 is before the initial frame 5").
std::variant<std::vector<Frame>, std::string> plan_frames(const AnimationOptions& animation,
                                                          const std::filesystem::path& output);

/// POV-Ray's frame file name: the number, zero-padded to `digits`, between the stem and the extension.
std::filesystem::path frame_file_name(const std::filesystem::path& output, int number, int digits);

}  // namespace wardray::app
