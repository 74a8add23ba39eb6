// PNG encoding and the writer thread, frame name patterns, and the figure's frame choice.
#include <gtest/gtest.h>

#include <random>

#include "core/errors.hpp"
#include "output/contact_sheet.hpp"
#include "output/frame_pattern.hpp"
#include "output/png_codec.hpp"
#include "output/png_writer.hpp"
#include "scene/frame_pattern_check.hpp"
#include "test_context.hpp"

namespace {

softbody::Image noise_image(int width, int height, unsigned seed) {
  softbody::Image image(width, height);
  std::mt19937 random(seed);
  for (std::uint8_t& v : image.rgb) v = static_cast<std::uint8_t>(random() & 0xff);
  return image;
}

TEST(Png, EncodeThenDecodeGivesTheSamePixels) {
  // Odd sizes and random bytes: no row padding or filter assumption can hide.
  const softbody::Image original = noise_image(37, 23, 7);
  const softbody::Image decoded = output::decode_png(output::encode_png(original));
  EXPECT_EQ(decoded.width, original.width);
  EXPECT_EQ(decoded.height, original.height);
  EXPECT_TRUE(decoded.rgb == original.rgb);
}

TEST(Png, DecodingSomethingElseFailsWithItsName) {
  try {
    output::decode_png("not a png at all", "bogus.png");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bogus.png"), std::string::npos) << e.what();
  }
}

TEST(PngWriter, WritesEveryQueuedFrameUnderItsFinalName) {
  const std::filesystem::path dir = render_test::fresh_output_dir("png_writer");
  std::vector<softbody::Image> images;
  {
    output::PngWriter writer(2);
    for (int i = 0; i < 6; ++i) {  // more frames than the queue holds: write() must wait, not drop
      images.push_back(noise_image(16, 8, static_cast<unsigned>(i)));
      writer.write(dir / output::frame_file_name("frame_%04d.png", i), images.back());
    }
    writer.finish();
    EXPECT_EQ(writer.timings().frames, 6);
  }
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos);
  }
  EXPECT_EQ(files, 6);
  for (int i = 0; i < 6; ++i) {
    EXPECT_TRUE(output::read_png(dir / output::frame_file_name("frame_%04d.png", i)).rgb == images[i].rgb);
  }
}

TEST(PngWriter, ReportsAFailedWrite) {
  output::PngWriter writer(1);
  writer.write("/proc/no_such_dir/frame.png", noise_image(4, 4, 1));  // cannot be created
  EXPECT_THROW(writer.finish(), std::runtime_error);
}

TEST(FramePattern, AcceptsPrintfIntegerPatternsFfmpegReads) {
  EXPECT_NO_THROW(scene::check_frame_pattern("frame_%04d.png", "s.json"));
  EXPECT_NO_THROW(scene::check_frame_pattern("%d.png", "s.json"));
  EXPECT_EQ(output::frame_file_name("frame_%04d.png", 7), "frame_0007.png");
  for (const char* bad : {"frame.png", "frame_%s.png", "frame_%04d_%d.png", "frame_%04d.jpg", "a/frame_%04d.png"}) {
    try {
      scene::check_frame_pattern(bad, "s.json");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const softbody::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("output.pattern"), std::string::npos) << e.what();
    }
  }
}

TEST(ContactSheet, FramesAreEvenlySpacedFromFirstToLast) {
  EXPECT_EQ(output::evenly_spaced_frames(8, 90), (std::vector<int>{0, 13, 26, 39, 51, 64, 77, 90}));
  EXPECT_EQ(output::evenly_spaced_frames(1, 90), (std::vector<int>{0}));
  EXPECT_EQ(output::evenly_spaced_frames(5, 2), (std::vector<int>{0, 1, 2}));  // fewer frames than tiles
  EXPECT_TRUE(output::evenly_spaced_frames(0, 90).empty());
}

TEST(ContactSheet, ShrinksWideFramesToKeepRowsWithin2560Pixels) {
  const output::ContactSheet sheet(output::evenly_spaced_frames(8, 90), 1280, 720);
  EXPECT_EQ(sheet.columns(), 4);
  EXPECT_EQ(sheet.shrink_factor(), 2);
  EXPECT_EQ(sheet.image().width, 8 + 4 * (640 + 8));
  EXPECT_EQ(sheet.image().height, 8 + 2 * (360 + 8));
}

TEST(ContactSheet, ShrinkingAveragesInLinearLight) {
  // A 2×2 checker of black and white averages to half the light: sRGB 188, not the naive 128.
  // Four 1280-wide frames in a row are shrunk by 2, so each tile pixel averages a 2×2 block.
  output::ContactSheet wide({0, 1, 2, 3}, 1280, 2);
  softbody::Image frame(1280, 2);
  for (int x = 0; x < 1280; ++x) {
    for (int y = 0; y < 2; ++y) {
      std::uint8_t* p = frame.pixel(x, y);
      p[0] = p[1] = p[2] = ((x + y) % 2 == 0) ? 255 : 0;
    }
  }
  wide.add(0, frame);
  ASSERT_EQ(wide.shrink_factor(), 2);
  EXPECT_NEAR(wide.image().pixel(8, 8)[0], 188, 1);
  EXPECT_FALSE(wide.complete());
}

}  // namespace
