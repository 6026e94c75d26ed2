// Reading a ParaView collection (.pvd), such as the frames.pvd a run writes (pvd_series.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sph::io {

// The frames a collection lists, in its order: (time, file relative to the .pvd's folder, its
// XML escapes undone), as PvdSeries writes them and ParaView reads them. `file` only names the
// collection in errors. Throws InputError naming it and what was wrong: not a VTK collection, a
// DataSet without a numeric timestep or a file, or a file outside the collection's folder
// (absolute, or through "..").
std::vector<std::pair<double, std::string>> readPvd(const std::string& bytes,
                                                    const std::filesystem::path& file);

}  // namespace sph::io
