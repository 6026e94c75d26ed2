// Any bytes as a frame of the format SPH_FUZZ_FILE names ("fuzz.vtp", "fuzz.ply", "fuzz.csv"),
// as a parallel frame's list of pieces ("fuzz.pvtp"), or as a run's frames.pvd ("fuzz.pvd"), as sph render reads them back: a frame (or the frames
// listed) or an InputError naming the file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "sph/io/frame_reader.hpp"
#include "io/pvd_reader.hpp"
#include "io/pvtp_reader.hpp"
#include "sph/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path file(SPH_FUZZ_FILE);
  try {
    if (file.extension() == ".vtp")
      sph::io::readVtp(bytes, file);
    else if (file.extension() == ".ply")
      sph::io::readPly(bytes, file);
    else if (file.extension() == ".pvd")
      sph::io::readPvd(bytes, file);
    else if (file.extension() == ".pvtp")
      sph::io::readPvtpPieces(bytes, file);
    else
      sph::io::readCsvFrame(bytes, file);
  } catch (const sph::InputError&) {
  }
  return 0;
}
