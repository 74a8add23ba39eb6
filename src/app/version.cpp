// What `softbody --version` prints.
#include "app/version.hpp"

#include "setup/build_fingerprint.hpp"

namespace app {

std::string version_text() {
  return std::string("softbody ") + SOFTBODY_VERSION + " (commit " + source_commit() + ", build " +
         std::string(setup::build_fingerprint()).substr(0, 16) + ")\n" +
         "Copyright (C) 2026 the softbody authors.\n"
         "Licence " +
         kLicence +
         ": GNU General Public License version 3 or later <https://www.gnu.org/licenses/gpl-3.0.html>.\n"
         "This is free software: you are free to change and redistribute it. There is NO WARRANTY, to the extent\n"
         "permitted by law. It links third-party libraries under their own licences: THIRD_PARTY_NOTICES.md\n"
         "(installed in share/doc/softbody/).";
}

}  // namespace app
