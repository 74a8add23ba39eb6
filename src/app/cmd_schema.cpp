// `softbody schema [--markdown]`: the JSON Schema of scene files, or the guide's key reference, both from the
// table the parser reads its keys from.
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "core/errors.hpp"
#include "scene/scene_schema.hpp"

namespace app {

Action register_schema(CLI::App& parent) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* command = parent.add_subcommand(
      "schema", "Print the JSON Schema (draft 2020-12) of scene files, for editors and validators");
  command->add_flag("--markdown", *markdown, "Print the key reference in Markdown instead (docs/guide/scene-keys.md)");
  return [markdown] {
    if (*markdown) {
      std::cout << scene::scene_key_reference();
    } else {
      std::cout << scene::scene_schema().dump(2) << "\n";
    }
    std::cout.flush();
    return std::cout ? softbody::kExitOk : softbody::kExitFailure;
  };
}

}  // namespace app
