// Refusing outputs that are the run's own inputs.
#include "output/input_guard.hpp"

#include <cctype>

#include "core/errors.hpp"

namespace output {
namespace {

namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;  // false when either does not exist
}

[[noreturn]] void refuse(const std::string& option, const fs::path& target, const InputFile& input) {
  throw softbody::InputError(option + " " + target.string() + ": is " + input.role + " (" + input.path.string() +
                             ") that the run reads: expected an output path other than its inputs");
}

}  // namespace

bool is_input(const fs::path& file, const std::vector<InputFile>& inputs) {
  for (const InputFile& input : inputs) {
    if (same_file(file, input.path)) return true;
  }
  return false;
}

void refuse_output_onto_inputs(const fs::path& target, const std::vector<InputFile>& inputs,
                               const std::string& option) {
  for (const InputFile& input : inputs) {
    if (same_file(target, input.path)) refuse(option, target, input);
  }
}

void refuse_numbered_outputs_onto_inputs(const fs::path& dir, int last, const std::function<fs::path(int)>& name_of,
                                         const std::vector<InputFile>& inputs, const std::string& option) {
  for (const InputFile& input : inputs) {
    if (!same_file(input.path.parent_path().empty() ? "." : input.path.parent_path(), dir)) continue;
    // Every run of digits in the input's name is a frame number it could be written as.
    const std::string name = input.path.filename().string();
    for (std::size_t start = 0; start < name.size();) {
      if (!std::isdigit(static_cast<unsigned char>(name[start]))) {
        ++start;
        continue;
      }
      std::size_t end = start;
      while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
      if (end - start <= 9) {
        const int frame = std::stoi(name.substr(start, end - start));
        if (frame <= last && name_of(frame) == fs::path(name)) refuse(option, dir / name, input);
      }
      start = end;
    }
  }
}

}  // namespace output
