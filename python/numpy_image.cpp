// numpy arrays to and from the program's images.
#include "numpy_image.hpp"

#include <cstring>
#include <string>

namespace py = pybind11;

namespace softbody_python {

py::array_t<std::uint8_t> to_numpy(const softbody::Image& image) {
  py::array_t<std::uint8_t> array({py::ssize_t{image.height}, py::ssize_t{image.width}, py::ssize_t{3}});
  std::memcpy(array.mutable_data(), image.rgb.data(), image.rgb.size());
  return array;
}

softbody::Image from_numpy(const py::array& array) {
  if (array.ndim() != 3 || array.shape(2) != 3 || array.shape(0) < 1 || array.shape(1) < 1) {
    throw py::value_error("expected an image of shape (height, width, 3), got shape " +
                          py::repr(array.attr("shape")).cast<std::string>());
  }
  const auto pixels = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(array);
  softbody::Image image(static_cast<int>(array.shape(1)), static_cast<int>(array.shape(0)));
  std::memcpy(image.rgb.data(), pixels.data(), image.rgb.size());
  return image;
}

}  // namespace softbody_python
