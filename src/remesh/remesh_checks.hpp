#pragma once
// Validation of RemeshSettings (remesh.hpp), one error per field.

#include <isopatch/remesh.hpp>

namespace isopatch {

/// \throw SettingError naming the first field of `s` out of its documented range.
void check_remesh_settings(const RemeshSettings& s);

}  // namespace isopatch
