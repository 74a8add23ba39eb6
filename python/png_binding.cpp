// softbody.read_png(path) and softbody.write_png(path, image): the program's PNG codec for numpy images, so that a
// golden-image test needs nothing beside numpy.
#include <filesystem>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "numpy_image.hpp"
#include "output/atomic_file.hpp"
#include "output/png_codec.hpp"

namespace py = pybind11;

namespace softbody_python {

void register_png(py::module_& module) {
  module.def(
      "read_png", [](const std::filesystem::path& path) { return to_numpy(output::read_png(path)); }, py::arg("path"),
      "Decodes an 8-bit RGB PNG file (the program's frames) into a numpy array (height, width, 3) uint8.");
  module.def(
      "write_png",
      [](const std::filesystem::path& path, const py::array& image) {
        output::write_file_atomically(path, output::encode_png(from_numpy(image)));
      },
      py::arg("path"), py::arg("image"),
      "Writes a numpy image (height, width, 3) of 0..255 values as an 8-bit RGB PNG file (whole or not at all).");
}

}  // namespace softbody_python
