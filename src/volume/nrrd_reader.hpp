#pragma once
// The NRRD reader (attached data, raw or gzip encoding) behind decode_volume (volume_io.hpp).

#include <isopatch/volume.hpp>

#include <string>
#include <string_view>

namespace isopatch::volume_io {

/// A 3-dimensional NRRD volume of a scalar type, with spacing and origin from its header.
/// \throw IoError("<name>: ...") for anything else.
Volume decode_nrrd(std::string_view bytes, const std::string& name);

}  // namespace isopatch::volume_io
