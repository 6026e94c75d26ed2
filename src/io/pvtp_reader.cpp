#include "io/pvtp_reader.hpp"

#include <algorithm>
#include <numeric>

#include "io/frame_reader_support.hpp"
#include "io/xml_attributes.hpp"
#include "sph/io/frame_reader.hpp"

namespace sph::io {

std::vector<std::string> readPvtpPieces(const std::string& bytes,
                                        const std::filesystem::path& file) {
  if (bytes.find("<VTKFile") == std::string::npos || bytes.find("PPolyData") == std::string::npos)
    throwBadFrame(file,
                  "not a parallel VTK PolyData file (.pvtp): no <VTKFile type=\"PPolyData\">");
  std::vector<std::string> pieces;
  for (std::size_t at = bytes.find("<Piece"); at != std::string::npos;
       at = bytes.find("<Piece", at + 1)) {
    const std::size_t end = bytes.find('>', at);
    if (end == std::string::npos) throwBadFrame(file, "a Piece element is not closed");
    const std::string which = "Piece " + std::to_string(pieces.size() + 1);
    const std::optional<std::string> source =
        xmlAttribute(bytes.substr(at + 6, end - at - 6), "Source");
    if (!source) throwBadFrame(file, which + ": expected a Source");
    const std::string relative = unescapeXmlAttribute(*source);
    if (!staysInsideFolder(relative) || std::filesystem::path(relative).extension() != ".vtp")
      throwBadFrame(file, which + ": Source \"" + source->substr(0, 80) +
                              "\" is not a .vtp file inside the frame's folder");
    pieces.push_back(relative);
  }
  if (pieces.empty()) throwBadFrame(file, "lists no Piece");
  return pieces;
}

ParticleFrame joinPvtpPieces(const std::vector<std::string>& pieces,
                             const std::filesystem::path& file) {
  std::vector<ParticleFrame> read;
  std::size_t n = 0;
  bool torn = true;
  for (const std::string& piece : pieces) {
    read.push_back(readFrame(file.parent_path() / piece));
    n += read.back().size();
    torn = torn && read.back().torn.size() == read.back().size();
  }
  ParticleFrame joined;
  joined.time = read.front().time;
  joined.step = read.front().step;
  for (const ParticleFrame& f : read) {
    joined.id.insert(joined.id.end(), f.id.begin(), f.id.end());
    joined.position.insert(joined.position.end(), f.position.begin(), f.position.end());
    joined.velocity.insert(joined.velocity.end(), f.velocity.begin(), f.velocity.end());
    joined.density.insert(joined.density.end(), f.density.begin(), f.density.end());
    joined.pressure.insert(joined.pressure.end(), f.pressure.begin(), f.pressure.end());
    joined.kind.insert(joined.kind.end(), f.kind.begin(), f.kind.end());
    joined.object.insert(joined.object.end(), f.object.begin(), f.object.end());
    joined.surface.insert(joined.surface.end(), f.surface.begin(), f.surface.end());
    if (torn) joined.torn.insert(joined.torn.end(), f.torn.begin(), f.torn.end());
  }
  // Into id order, as a frame of one process is.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return joined.id[a] < joined.id[b]; });
  ParticleFrame out;
  out.time = joined.time;
  out.step = joined.step;
  resizeFrame(out, n);
  if (torn) out.torn.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    if (k > 0 && joined.id[i] == out.id[k - 1])
      throwBadFrame(file, "two pieces hold particle " + std::to_string(joined.id[i]));
    out.id[k] = joined.id[i];
    std::copy_n(&joined.position[3 * i], 3, &out.position[3 * k]);
    std::copy_n(&joined.velocity[3 * i], 3, &out.velocity[3 * k]);
    out.density[k] = joined.density[i];
    out.pressure[k] = joined.pressure[i];
    out.kind[k] = joined.kind[i];
    out.object[k] = joined.object[i];
    out.surface[k] = joined.surface[i];
    if (torn) out.torn[k] = joined.torn[i];
  }
  return out;
}

}  // namespace sph::io
