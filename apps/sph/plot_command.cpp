// sph plot DIR: a run's statistics (DIR/stats.csv) and probes (DIR/probes.csv) drawn against
// time by gnuplot, as DIR/plots/stats.png and DIR/plots/probes.png.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "commands.hpp"

namespace sph::cli {

namespace {

namespace fs = std::filesystem;

// The names in a CSV file's first line.
std::vector<std::string> headerOf(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::string name;
  for (char c : line) {
    if (c == ',') {
      names.push_back(name);
      name.clear();
    } else if (c != '\r') {
      name += c;
    }
  }
  if (!name.empty()) names.push_back(name);
  return names;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A string in gnuplot's single quotes, where '' stands for one quote.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A line of one column against the first ("time" or "time_s"), titled `title`.
std::string series(const fs::path& file, const std::string& time, const std::string& column,
                   const std::string& title) {
  return quoted(file.string()) + " using " + quoted(time) + ":" + quoted(column) +
         " with lines title " + quoted(title);
}

// One panel a quantity: the columns ending in `unit` of one probe, or a statistic.
struct Panel {
  std::string title;
  std::string axis;
  std::vector<std::pair<std::string, std::string>> lines;  // column, title
  bool logarithmic = false;
};

std::string script(const fs::path& file, const std::string& time, const std::vector<Panel>& panels,
                   const fs::path& png) {
  const int rows = int(panels.size() + 1) / 2;
  // noenhanced: probe names are printed as written, an underscore not a subscript.
  std::string s = "set terminal pngcairo noenhanced size 1200," + std::to_string(300 * rows) +
                  " font ',10'\n"
                  "set output " +
                  quoted(png.string()) +
                  "\n"
                  "set datafile separator ','\n"
                  "set datafile missing 'nan'\n"
                  "set grid\n"
                  // A constant line would sit on the frame: room above and below.
                  "set offsets 0, 0, graph 0.05, graph 0.05\n"
                  "set key top right\n"
                  "set xlabel 'time (s)'\n"
                  "set multiplot layout " +
                  std::to_string(rows) + "," + std::to_string(panels.size() > 1 ? 2 : 1) + "\n";
  for (const Panel& p : panels) {
    s += "set title " + quoted(p.title) + "\nset ylabel " + quoted(p.axis) + "\n";
    s += p.logarithmic ? "set logscale y\n" : "unset logscale y\n";
    s += "plot ";
    for (std::size_t k = 0; k < p.lines.size(); ++k)
      s += (k ? ", " : "") + series(file, time, p.lines[k].first, p.lines[k].second);
    s += "\n";
  }
  return s + "unset multiplot\n";
}

std::vector<Panel> statsPanels() {
  return {{"fastest particle", "m/s", {{"max_speed", "max speed"}}},
          {"density error",
           "rho/rho0 - 1",
           {{"max_density_error", "largest"}, {"average_density_error", "average"}}},
          {"time step", "s", {{"dt", "dt"}}, true},
          {"kinetic energy", "J", {{"kinetic_energy", "fluid"}}},
          {"fluid particles",
           "count",
           {{"fluid_count", "in the domain"},
            {"leaked_count", "leaked"},
            {"removed_count", "removed"}}},
          {"cost", "ms per step", {{"wall_ms_per_step", "wall"}}}};
}

// A panel per probe: a point's pressure, a gauge's level, a force's components.
std::vector<Panel> probePanels(const std::vector<std::string>& columns) {
  std::vector<Panel> panels;
  for (const std::string& c : columns) {
    if (endsWith(c, "_pressure_Pa")) {
      const std::string name = c.substr(0, c.size() - 12);
      panels.push_back({name + " (point)", "pressure (Pa)", {{c, "p"}}});
    } else if (endsWith(c, "_level_m")) {
      const std::string name = c.substr(0, c.size() - 8);
      panels.push_back({name + " (level)", "level (m)", {{c, "level"}}});
    } else if (endsWith(c, "_fx_N")) {
      const std::string name = c.substr(0, c.size() - 5);
      panels.push_back({name + " (force)",
                        "force (N)",
                        {{c, "x"}, {name + "_fy_N", "y"}, {name + "_fz_N", "z"}}});
    }
  }
  return panels;
}

// Runs gnuplot on `text`; whether it succeeded.
bool runGnuplot(const std::string& text) {
  std::FILE* gnuplot = popen("gnuplot", "w");
  if (gnuplot == nullptr) return false;
  std::fputs(text.c_str(), gnuplot);
  return pclose(gnuplot) == 0;
}

}  // namespace

int plotCommand(const PlotOptions& options) {
  const fs::path dir = options.dir;
  const fs::path stats = dir / "stats.csv", probes = dir / "probes.csv";
  if (!fs::exists(stats)) {
    std::fprintf(stderr, "error: %s: no stats.csv: expected the directory of a run (sph run)\n",
                 dir.string().c_str());
    return kExitBadInput;
  }
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    std::fprintf(stderr, "error: gnuplot not found (scripts/install-deps installs it)\n");
    return 1;
  }
  const fs::path out = dir / "plots";
  std::error_code error;
  fs::create_directories(out, error);
  if (error) {
    std::fprintf(stderr, "error: %s: cannot create it: %s\n", out.string().c_str(),
                 error.message().c_str());
    return 1;
  }
  std::vector<std::pair<fs::path, std::string>> jobs = {
      {out / "stats.png", script(stats, "time", statsPanels(), out / "stats.png")}};
  if (fs::exists(probes)) {
    const std::vector<Panel> panels = probePanels(headerOf(probes));
    if (!panels.empty())
      jobs.push_back({out / "probes.png", script(probes, "time_s", panels, out / "probes.png")});
  }
  for (const auto& [png, text] : jobs) {
    if (!runGnuplot(text)) {
      std::fprintf(stderr, "error: gnuplot failed to draw %s\n", png.string().c_str());
      return 1;
    }
    if (!options.quiet) std::printf("%s\n", png.string().c_str());
  }
  return kExitOk;
}

}  // namespace sph::cli
