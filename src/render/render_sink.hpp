// The render command's frame sink: every frame of the run becomes a rendered image that goes to PNG
// files (on the writer thread), an ffmpeg video and the figure, with each stage timed.
//
//   World ─► snapshot_surfaces ─► Renderer::draw ─► read_back ─┬─► VideoWriter thread ─► ffmpeg stdin
//                                                              ├─► ContactSheet (chosen frames)
//                                                              └─► PngWriter queue ─► frame_%04d.png
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frames/capturing_sink.hpp"
#include "output/contact_sheet.hpp"
#include "output/png_writer.hpp"
#include "output/video_writer.hpp"
#include "render/renderer.hpp"

namespace render {

// What the render run writes.
struct RenderOutputs {
  std::filesystem::path dir;                   // PNG frames and figure.png
  std::string pattern = "frame_%04d.png";      // checked with scene::check_frame_pattern
  bool write_frames = true;                    // the PNG sequence
  std::optional<std::filesystem::path> video;  // an MP4 when set
  int fps = 30;                                // the video's frame rate
  int figure_frames = 8;                       // tiles in figure.png, evenly spaced; 0: no figure
  std::vector<int> figure_frame_list;          // when not empty: exactly these frames (chosen from the motion,
                                               // or render.figure_frames as a list), instead of figure_frames
  int last_frame = 0;                          // index of the run's last frame (frame 0 is the initial state)
  bool remove_stale_frames = true;             // remove frame files numbered after last_frame (a longer earlier run's)
  // A resumed run (--resume): frames 0 .. resumed_after are already on disk (the figure takes its tiles of
  // them from there). With resume, the video is made when the run completes, from the PNG files, rather
  // than piped while rendering (a killed ffmpeg cannot be continued): the same frames into the same pipe.
  int resumed_after = -1;
  bool video_from_files = false;
  // When set: called on the PNG writer's thread after each frame file is in place, with its bytes.
  std::function<void(const std::filesystem::path&, std::string_view)> frame_stored;
};

// Wall-clock time of each stage, summed over the frames [s]. Read by the summary line and benchmarks.
struct RenderTimings {
  int frames = 0;
  double snapshot_s = 0.0;       // World → FrameMesh
  double render_s = 0.0;         // normals, uploads, shadow and main passes, MSAA resolve, glFinish
  double read_back_s = 0.0;      // glReadPixels and the flip into an Image
  double video_s = 0.0;          // render thread: handing frames to the video writer thread (a copy, or waiting
                                 // for its queue), and waiting for ffmpeg to finish
  double figure_s = 0.0;         // shrinking frames into the contact sheet and writing figure.png
  double queue_wait_s = 0.0;     // render thread blocked on a full PNG queue
  output::PngWriterTimings png;  // on the writer thread: encode and store
};

class RenderSink final : public frames::CapturingFrameSink {
 public:
  // Starts the PNG writer and ffmpeg (when asked for); `renderer` must outlive the sink.
  RenderSink(Renderer& renderer, RenderOutputs outputs);

  // Copies the bodies' surfaces (positions and triangles) out of the world.
  void capture(int index, double time_s, const sim::World& world) override;
  // Renders the captured surfaces and hands the image to the outputs; never reads the world, so the
  // world may step meanwhile (frames::run_frames_overlapped).
  void deliver() override;
  // Complete: drains the PNG queue, finishes the video, writes figure.png, removes stale frames numbered
  // after the last one (left by an earlier, longer run, they would end up in `ffmpeg -i pattern`).
  // Incomplete: drains the PNG queue (those frames are valid) and abandons the video and the figure.
  void finish(bool complete) override;

  RenderTimings timings() const;
  // Paths of what finish(true) wrote, for the summary.
  std::optional<std::filesystem::path> figure_path() const;

 private:
  void write_figure();
  // "t = 0.63 s": the simulated time of frame `index` (frame k is at k / fps).
  std::string time_label(int index) const;
  void remove_stale_frames() const;
  // The video from the PNG files 0 .. last_frame (video_from_files).
  void encode_video_from_files();

  Renderer& renderer_;
  RenderOutputs outputs_;
  std::vector<FrameMesh> meshes_;  // the captured frame
  int captured_index_ = 0;
  double captured_time_s_ = 0.0;  // the captured frame's simulated time (a keyframed collider's pose)
  softbody::Image frame_;
  std::optional<output::PngWriter> png_writer_;
  std::unique_ptr<output::VideoWriter> video_;  // ffmpeg fed from its own thread
  std::optional<output::ContactSheet> figure_;
  bool figure_written_ = false;
  RenderTimings timings_;
};

}  // namespace render
