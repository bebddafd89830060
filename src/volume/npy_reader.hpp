#pragma once
// The .npy reader (numpy's format, versions 1 to 3) behind decode_volume (volume_io.hpp).

#include <isopatch/volume.hpp>

#include <string>
#include <string_view>

namespace isopatch::volume_io {

/// A 3-dimensional array of a scalar type (volume_io.hpp); spacing 1 and origin 0.
/// \throw IoError("<name>: ...") for anything else.
Volume decode_npy(std::string_view bytes, const std::string& name);

}  // namespace isopatch::volume_io
