#pragma once

// The JSON objects of `vantage design --json` and `vantage weights --json` (the contracts are the
// "vantage design" and "vantage weights" sections of README.md), and the layout that
// `vantage design --write` writes. Shared by the `vantage` command and the Python module
// (vantage.design, vantage.weights), so that both print exactly the same fields.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/design/augment.h"
#include "vantage/design/weights.h"

namespace vantage::design_json {

using Json = nlohmann::ordered_json;

/// The report of augmenting `layout` into `r`. `source` is the "layout" field (the file name, or
/// null for a layout given in memory); `direct_asked` adds "direct_message" when the direct
/// search was asked for and did not run.
Json design(const Json& source, const Layout& layout, bool direct_asked,
            const design::AugmentResult& r);

/// The report of the Prop. 3 weights `w` of `layout`; `source` as in design().
Json weights(const Json& source, const Layout& layout, const design::Weights& w);

/// What design says of a layout with a visibility model (normals, cones, body or workspace),
/// which its search does not use (issue 36): the sentence the command prints as a warning line
/// and Python raises as a RuntimeWarning; nullopt for a layout seen whole.
std::optional<std::string> unused_visibility_warning(const Layout& layout);

/// The augmented layout as written: the greedy additions appended, the candidates that were used
/// dropped (they are markers or directions of the layout now): AugmentResult::augmented.
Layout layout_to_write(const design::AugmentResult& result);

}  // namespace vantage::design_json
