// Pictures between the program (softbody::Image: 8-bit RGB rows, top first) and numpy ((height, width, 3) uint8).
#pragma once

#include <pybind11/numpy.h>

#include "core/image.hpp"

namespace softbody_python {

// A new (height, width, 3) uint8 array with the image's pixels.
pybind11::array_t<std::uint8_t> to_numpy(const softbody::Image& image);

// The image of an (height, width, 3) array of 0..255 values (any integer type is converted); throws
// pybind11::value_error for another shape.
softbody::Image from_numpy(const pybind11::array& array);

}  // namespace softbody_python
