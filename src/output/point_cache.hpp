// Point caches for 3D packages: per body, the mesh once as OBJ and the positions of every frame as a PC2
// (3ds Max Point Cache 2) or MDD file, which Blender's Mesh Cache modifier, Maya and Houdini read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frames/frame_sink.hpp"
#include "output/shown_surface.hpp"

namespace output {

enum class PointCacheFormat { Pc2, Mdd };

// The samples of one body: `points` vertices per sample, x y z floats in sample order.
struct PointSamples {
  int points = 0;
  std::vector<float> xyz;      // samples × points × 3
  std::vector<float> times_s;  // one per sample (simulated time)
  int samples() const { return static_cast<int>(times_s.size()); }
};

// PC2: little-endian; char[12] "POINTCACHE2\0", int32 version 1, int32 points, float start frame, float
// sample rate (frames between samples), int32 samples, then float x y z per point per sample.
std::string encode_pc2(const PointSamples& samples, float start_frame, float frames_per_sample);

// MDD: big-endian; int32 frames, int32 points, float time [s] per frame, then float x y z per point per frame.
std::string encode_mdd(const PointSamples& samples);

class PointCacheExporter final : public frames::FrameSink {
 public:
  // Writes DIR/body<N>.obj (the mesh at the first frame handed over: topology and its positions) and
  // DIR/body<N>.pc2 or .mdd (every frame handed over, the first being the cache's start frame) for each
  // body, at finish(), each file whole (temporary name, then rename). Frames must come one after another.
  PointCacheExporter(std::filesystem::path dir, PointCacheFormat format);
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool complete) override;

  std::filesystem::path mesh_path(int body) const;
  std::filesystem::path cache_path(int body) const;
  int body_count() const { return static_cast<int>(bodies_.size()); }

 private:
  std::filesystem::path dir_;
  PointCacheFormat format_;
  int first_frame_ = -1;
  int last_frame_ = -1;
  std::vector<std::string> meshes_obj_;  // per body, from the first frame
  std::vector<PointSamples> bodies_;
  ShownPositions shown_;  // the skins' scratch
};

// One body of `world` as OBJ text ("o body<N>", its vertices, 1-based faces).
std::string body_to_obj(const sim::World& world, int body, double time_s);

}  // namespace output
