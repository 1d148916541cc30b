// Where the bundled data (couplings, models, recordings) is, for a program run from its build tree
// and for an installed one alike (docs/deploy.md).
#pragma once

#include <filesystem>
#include <string_view>

namespace gc::codec {

/// The directory of the bundled data `kind` ("couplings", "models", "recordings"): the first that
/// exists of
///   1. share/gearcoupling/<kind> beside the installed gearcoupling-codec library, found from the
///      library's own path: any install prefix, a .deb, a copy of the install tree;
///   2. data/<kind> of the source tree this was built from: a program run from its build tree;
///   3. share/gearcoupling/<kind> under the install prefix this was configured with.
/// The last when none exists.
std::filesystem::path bundled_data_dir(std::string_view kind);

}  // namespace gc::codec
