#include <iostream>

#include "apps/parkloc/command.h"
#include "io/sequence.h"
#include "io/sequence_video.h"

namespace {

struct ConvertArgs {
  std::string sequence, out;
  parkloc::io::SequenceVideoOptions video;
};

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<ConvertArgs>();
  auto* cmd = parent.add_subcommand(
      "convert", "Write a sequence's image folders as one video per camera (videos/ layout)");
  cmd->add_option("sequence", args->sequence, "Sequence folder")->required();
  cmd->add_option("--out", args->out, "New sequence folder")->required();
  cmd->add_option("--fourcc", args->video.fourcc, "Codec FourCC (MJPG, avc1 for H.264, mp4v, ...)")
      ->capture_default_str();
  cmd->add_option("--ext", args->video.extension, "Video file extension (.avi, .mp4, ...)")
      ->capture_default_str();
  cmd->add_option("--quality", args->video.mjpeg_quality, "JPEG quality of MJPG frames (1-100)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("--fps", args->video.fps, "Nominal frame rate of the container")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->callback([args] {
    // A survey drive has no map yet: convert needs only the recording (the map and the other
    // files are copied as they are, when present).
    const parkloc::io::Sequence sequence(args->sequence, "", "", "",
                                         parkloc::io::SequenceContents::kSensors);
    parkloc::io::writeSequenceVideos(sequence, args->out, args->video);
    std::cout << "wrote " << sequence.cameras().size() << " videos of "
              << sequence.timestamps().size() << " frame sets to " << args->out << "/videos\n";
  });
});

}  // namespace
