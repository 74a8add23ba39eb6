// Outputs that would replace the run's own inputs: `--csv scene.json` wrote the CSV over the scene it read.
// Refused before any output is touched, by file identity (the same device and inode: hard and symbolic links
// too), so that no spelling of a path gets past.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace output {

// An input of the run, named for messages: "the scene file", "the mesh file of bodies.0".
struct InputFile {
  std::filesystem::path path;
  std::string role;
};

// Throws softbody::InputError ("--csv a.json: is the scene file the run reads: expected another output file")
// when `target` exists and is one of `inputs`. `option` names where the target comes from ("--csv").
void refuse_output_onto_inputs(const std::filesystem::path& target, const std::vector<InputFile>& inputs,
                               const std::string& option);

// True when `file` exists and is one of `inputs` (the same file, whatever the spelling).
bool is_input(const std::filesystem::path& file, const std::vector<InputFile>& inputs);

// The same for numbered outputs: the files `name_of(0)` .. `name_of(last)` in `dir` (a run's frames, which a
// new run also removes first). Looks only at the inputs inside `dir`, and only at their own names' numbers.
void refuse_numbered_outputs_onto_inputs(const std::filesystem::path& dir, int last,
                                         const std::function<std::filesystem::path(int)>& name_of,
                                         const std::vector<InputFile>& inputs, const std::string& option);

}  // namespace output
