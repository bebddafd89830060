// libFuzzer target: the volume readers. The first byte picks the format (even: .npy, odd: NRRD), the
// rest is the file. decode_volume must return a volume that passes Volume::validate() or throw IoError
// with a one-line message naming the file; nothing may allocate more than the input can hold (a
// header declaring huge sizes must fail before the allocation; libFuzzer's -rss_limit_mb catches it).
#include <isopatch/error.hpp>
#include <isopatch/volume_io.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const isopatch::VolumeFormat format =
      data[0] % 2 == 0 ? isopatch::VolumeFormat::Npy : isopatch::VolumeFormat::Nrrd;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const isopatch::Volume volume = isopatch::decode_volume(bytes, format, "fuzz.input");
    volume.validate();
  } catch (const isopatch::IoError& e) {
    const std::string message = e.what();
    if (message.rfind("fuzz.input", 0) != 0 || message.find('\n') != std::string::npos) std::abort();
  }
  return 0;
}
