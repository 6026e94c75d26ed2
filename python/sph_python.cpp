// The Python module sph._sph: scenes, simulations and their particles as numpy arrays. The
// Python package python/sph/__init__.py adds what is easier said in Python (scenes from dicts,
// dotted keys, run with a callback).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sph/box_drop_scene.hpp"
#include "sph/error.hpp"
#include "sph/io/frame_reader.hpp"
#include "sph/io/frame_writer.hpp"
#include "sph/object_exchange.hpp"
#include "sph/scene_file.hpp"
#include "sph/simulation.hpp"

namespace py = pybind11;

namespace {

// A copy of `values` as a numpy array of `rows` rows of `columns` (1: a flat array).
template <class T>
py::array_t<T> toArray(const std::vector<T>& values, std::size_t rows, std::size_t columns) {
  std::vector<py::ssize_t> shape{py::ssize_t(rows)};
  if (columns > 1) shape.push_back(py::ssize_t(columns));
  py::array_t<T> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::dict frameArrays(const sph::ParticleFrame& f) {
  const std::size_t n = f.size();
  py::dict out;
  out["id"] = toArray(f.id, n, 1);
  out["position"] = toArray(f.position, n, 3);
  out["velocity"] = toArray(f.velocity, n, 3);
  out["density"] = toArray(f.density, n, 1);
  out["pressure"] = toArray(f.pressure, n, 1);
  out["kind"] = toArray(f.kind, n, 1);
  out["object"] = toArray(f.object, n, 1);
  out["surface"] = toArray(f.surface, n, 1);
  return out;
}

py::dict particles(const sph::Simulation& sim, bool includeBoundary) {
  sph::ParticleFrame f;
  {
    py::gil_scoped_release release;
    f = sim.frame(includeBoundary);
  }
  return frameArrays(f);
}

sph::FrameFormat formatNamed(const std::string& name) {
  if (name == "vtp") return sph::FrameFormat::Vtp;
  if (name == "ply") return sph::FrameFormat::Ply;
  if (name == "csv") return sph::FrameFormat::Csv;
  throw py::value_error("format: expected \"vtp\", \"ply\" or \"csv\", got \"" + name + "\"");
}

// A str or an os.PathLike as a path.
std::string pathOf(const py::object& path) {
  return py::cast<std::string>(py::module_::import("os").attr("fspath")(path));
}

// The frame as `sph run` writes it (output.format), to `path` as given.
void writeFrame(const sph::Simulation& sim, const py::object& pathLike, const std::string& format,
                bool includeBoundary) {
  const sph::FrameFormat f = formatNamed(format);
  const std::string path = pathOf(pathLike);
  py::gil_scoped_release release;
  sph::io::writeFrame(sim.frame(includeBoundary), f, path);
}

py::dict calibration(const sph::Simulation& sim) {
  const sph::Calibration& c = sim.calibration();
  py::dict out;
  out["spacing"] = c.spacing;
  out["support_radius"] = c.supportRadius;
  out["mass"] = c.mass;
  out["max_expected_speed"] = c.maxExpectedSpeed;
  out["sound_speed"] = c.soundSpeed;
  out["stiffness"] = c.stiffness;
  out["kinematic_viscosity"] = c.kinematicViscosity;
  out["initial_dt"] = c.initialDt;
  out["fluid_particles"] = c.fluidParticles;
  out["object_particles"] = c.objectParticles;
  out["boundary_particles"] = c.boundaryParticles;
  return out;
}

py::dict objectStats(const sph::ObjectStats& o) {
  py::dict out;
  out["name"] = o.name;
  out["mass"] = o.mass;
  out["centre_of_mass"] = o.centreOfMass;
  out["velocity"] = o.velocity;
  out["fluid_force"] = o.fluidForce;
  out["contact_force"] = o.contactForce;
  out["broken_springs"] = o.brokenSprings;
  out["volume_ratio"] = o.volumeRatio;  // 0 unless a liquid-filled vessel keeps its volume
  return out;
}

py::dict stats(const sph::Simulation& sim) {
  const sph::FrameStats s = sim.stats();
  py::dict out;
  out["time"] = s.time;
  out["steps"] = s.steps;
  out["dt"] = s.dt;
  out["fluid_count"] = s.fluidCount;
  out["boundary_count"] = s.boundaryCount;
  out["kinetic_energy"] = s.kineticEnergy;
  out["mean_density"] = s.meanDensity;
  out["average_density_error"] = s.averageDensityError;
  out["max_density_error"] = s.maxDensityError;
  out["max_speed"] = s.maxSpeed;
  out["surface_count"] = s.surfaceCount;
  out["leaked_count"] = s.leakedCount;
  out["removed_count"] = s.removedCount;
  out["emitted_count"] = s.emittedCount;
  out["clamped_count"] = s.clampedCount;
  out["density_iterations"] = s.densityIterations;
  out["divergence_iterations"] = s.divergenceIterations;
  out["unconverged_solves"] = s.unconvergedSolves;
  py::list objects;
  for (const sph::ObjectStats& o : s.objects) objects.append(objectStats(o));
  out["objects"] = objects;
  return out;
}

py::dict liveParameters(const sph::Simulation& sim) {
  const sph::LiveParameters p = sim.liveParameters();
  py::dict out;
  out["viscosity"] = p.viscosity;
  out["stiffness"] = p.stiffness;
  out["gravity"] = p.gravity;
  out["surface_tension"] = p.surfaceTension;
  out["influence_ratio"] = p.influenceRatio;
  return out;
}

// Changes the live parameters named in `changes`; a name that is not one is refused.
void setLiveParameters(sph::Simulation& sim, const py::dict& changes) {
  sph::LiveParameters p = sim.liveParameters();
  for (const auto& [key, value] : changes) {
    const std::string name = py::cast<std::string>(key);
    if (name == "viscosity")
      p.viscosity = py::cast<double>(value);
    else if (name == "stiffness")
      p.stiffness = py::cast<double>(value);
    else if (name == "gravity")
      p.gravity = py::cast<sph::Vec3d>(value);
    else if (name == "surface_tension")
      p.surfaceTension = py::cast<double>(value);
    else if (name == "influence_ratio")
      p.influenceRatio = py::cast<double>(value);
    else
      throw py::key_error("not a live parameter: '" + name +
                          "'; they are viscosity, stiffness, gravity, surface_tension, "
                          "influence_ratio");
  }
  sim.setLiveParameters(p);
}

// A FluidArrays used after the simulation stepped past it.
class StaleView : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The fluid's arrays in place (sph::FluidView), as numpy arrays that share its memory; on the
// CUDA backend, copies taken from a frame. Every read checks the view is still the
// simulation's current one: a view kept across a step would read particles that have moved and
// been reordered.
class FluidArrays {
 public:
  explicit FluidArrays(py::object simulation) : simulation_(std::move(simulation)) {
    view_ = sim().fluidView();
    if (!view_) {
      copy_ = sim().frame(false);
      copied_ = true;
      // The fluid comes first in a frame; an attached engine's objects follow it.
      std::size_t fluid = 0;
      while (fluid < copy_.size() && copy_.kind[fluid] == std::uint8_t(sph::ParticleKind::Fluid))
        ++fluid;
      view_.count = fluid;
      view_.step = copy_.step;
    }
  }
  std::size_t count() const {
    check();
    return view_.count;
  }
  bool copied() const { return copied_; }
  py::array id(py::handle self) const {
    check();
    return copied_ ? flat(copy_.id.data(), self) : flat(view_.id, self);
  }
  py::array position(py::handle self) const {
    check();
    return copied_ ? vectors(copy_.position.data(), 3, self)
                   : vectors(view_.position, sph::FluidView::kVectorStride, self);
  }
  py::array velocity(py::handle self) const {
    check();
    return copied_ ? vectors(copy_.velocity.data(), 3, self)
                   : vectors(view_.velocity, sph::FluidView::kVectorStride, self);
  }
  py::array density(py::handle self) const {
    check();
    return flat(copied_ ? copy_.density.data() : view_.density, self);
  }
  py::array pressure(py::handle self) const {
    check();
    return flat(copied_ ? copy_.pressure.data() : view_.pressure, self);
  }
  // Every row is a fluid particle's: 0 (a frame's kind), one byte shared by all rows.
  py::array kind(py::handle self) const {
    check();
    static const std::uint8_t fluid = std::uint8_t(sph::ParticleKind::Fluid);
    return readOnly(
        py::array_t<std::uint8_t>({py::ssize_t(view_.count)}, {py::ssize_t(0)}, &fluid, self));
  }

 private:
  const sph::Simulation& sim() const { return simulation_.cast<const sph::Simulation&>(); }

  void check() const {
    if (copied_) return;
    const sph::FluidView now = sim().fluidView();
    if (now.step != view_.step || now.id != view_.id || now.count != view_.count ||
        now.position != view_.position)
      throw StaleView("this view of the fluid was taken at step " + std::to_string(view_.step) +
                      " and the simulation is at step " + std::to_string(now.step) +
                      ": its arrays have moved on; take a new one with Simulation.view(), or "
                      "keep copies (numpy.copy) of what you need before stepping");
  }
  // Read-only: the arrays are the simulation's own.
  template <class T>
  py::array readOnly(py::array_t<T> a) const {
    a.attr("setflags")(py::arg("write") = false);
    return std::move(a);
  }
  template <class T>
  py::array flat(const T* data, py::handle self) const {
    return readOnly(
        py::array_t<T>({py::ssize_t(view_.count)}, {py::ssize_t(sizeof(T))}, data, self));
  }
  py::array vectors(const float* data, std::size_t stride, py::handle self) const {
    return readOnly(py::array_t<float>(
        {py::ssize_t(view_.count), py::ssize_t(3)},
        {py::ssize_t(stride * sizeof(float)), py::ssize_t(sizeof(float))}, data, self));
  }

  py::object simulation_;
  sph::FluidView view_;
  sph::ParticleFrame copy_;
  bool copied_ = false;
};

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// `array` as n rows of 3 (or of 1 when `columns` is 1); refuses another shape naming `name`.
const float* rowsOf(const FloatArray& array, std::size_t n, int columns, const char* name) {
  const bool ok = columns == 1 ? array.ndim() == 1 && std::size_t(array.shape(0)) == n
                               : array.ndim() == 2 && std::size_t(array.shape(0)) == n &&
                                     array.shape(1) == columns;
  if (!ok)
    throw py::value_error(std::string("ObjectExchange.publish: ") + name + ": expected shape (" +
                          std::to_string(n) + (columns == 1 ? ",)" : ", 3)") + ", got " +
                          py::cast<std::string>(py::str(array.attr("shape"))));
  return array.data();
}

// The engine's side of the exchange from Python: the surface particles of every object, as
// arrays of one row a particle; forces come back by handle (the row, unless `handle` says).
void publish(
    sph::ObjectExchange& exchange, const FloatArray& position, const FloatArray& velocity,
    const FloatArray& normal, const FloatArray& radius,
    const py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>& object,
    const std::optional<py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>>&
        handle,
    const std::optional<py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>>& cut,
    double time) {
  if (position.ndim() != 2 || position.shape(1) != 3)
    throw py::value_error("ObjectExchange.publish: position: expected shape (n, 3)");
  const std::size_t n = std::size_t(position.shape(0));
  const float* x = rowsOf(position, n, 3, "position");
  const float* v = rowsOf(velocity, n, 3, "velocity");
  const float* nrm = rowsOf(normal, n, 3, "normal");
  const float* r = rowsOf(radius, n, 1, "radius");
  const auto sizeOk = [&](py::ssize_t ndim, py::ssize_t rows, const char* name) {
    if (ndim != 1 || std::size_t(rows) != n)
      throw py::value_error(std::string("ObjectExchange.publish: ") + name + ": expected shape (" +
                            std::to_string(n) + ",)");
  };
  sizeOk(object.ndim(), object.shape(0), "object");
  if (handle) sizeOk(handle->ndim(), handle->shape(0), "handle");
  if (cut) sizeOk(cut->ndim(), cut->shape(0), "cut");
  sph::ObjectSurface& s = exchange.back();
  s.clear();
  for (std::size_t k = 0; k < n; ++k)
    s.add(sph::Vec3{x[3 * k], x[3 * k + 1], x[3 * k + 2]},
          sph::Vec3{v[3 * k], v[3 * k + 1], v[3 * k + 2]}, r[k],
          sph::Vec3{nrm[3 * k], nrm[3 * k + 1], nrm[3 * k + 2]},
          handle ? handle->data()[k] : std::uint32_t(k), object.data()[k],
          cut && cut->data()[k] != 0);
  s.time = time;
  exchange.publish();
}

py::tuple takeForces(sph::ObjectExchange& exchange) {
  std::vector<sph::Vec3> force;
  const double span = exchange.takeForces(force);
  py::array_t<float> out({py::ssize_t(force.size()), py::ssize_t(3)});
  float* f = out.mutable_data();
  for (std::size_t k = 0; k < force.size(); ++k) {
    f[3 * k] = force[k].x;
    f[3 * k + 1] = force[k].y;
    f[3 * k + 2] = force[k].z;
  }
  return py::make_tuple(out, span);
}

sph::Backend backendNamed(const std::string& name) {
  if (name == "cpu") return sph::Backend::Cpu;
  if (name == "cuda") return sph::Backend::Cuda;
  if (name == "auto") return sph::Backend::Auto;
  throw py::value_error("backend: expected \"cpu\", \"cuda\" or \"auto\", got \"" + name + "\"");
}

}  // namespace

PYBIND11_MODULE(_sph, m) {
  m.doc() = "SPH fluids and the objects in them (the sph library)";
  py::register_exception<sph::InputError>(m, "SceneError", PyExc_ValueError);
  py::register_exception<sph::SimulationFailure>(m, "SimulationFailure", PyExc_RuntimeError);
  py::register_exception<sph::OutputError>(m, "OutputError", PyExc_OSError);
  py::register_exception<StaleView>(m, "StaleViewError", PyExc_RuntimeError);

  py::class_<FluidArrays>(m, "FluidArrays",
                          "The fluid's arrays without copying (CPU backend), in the engine's "
                          "order: `id` says whose each row is. Valid until the simulation steps; "
                          "reading one after raises StaleViewError. On the CUDA backend, copies "
                          "ordered by id (`copied` is True).")
      .def_property_readonly("count", &FluidArrays::count)
      .def_property_readonly("copied", &FluidArrays::copied)
      .def_property_readonly(
          "id", [](py::object self) { return self.cast<const FluidArrays&>().id(self); })
      .def_property_readonly(
          "position",
          [](py::object self) { return self.cast<const FluidArrays&>().position(self); })
      .def_property_readonly(
          "velocity",
          [](py::object self) { return self.cast<const FluidArrays&>().velocity(self); })
      .def_property_readonly(
          "density", [](py::object self) { return self.cast<const FluidArrays&>().density(self); })
      .def_property_readonly(
          "pressure",
          [](py::object self) { return self.cast<const FluidArrays&>().pressure(self); })
      .def_property_readonly(
          "kind", [](py::object self) { return self.cast<const FluidArrays&>().kind(self); });

  py::class_<sph::Scene>(m, "Scene", "A checked scene: read with load_scene or scene_from_dict.")
      .def_property_readonly("source", [](const sph::Scene& s) { return s.sourcePath; })
      .def("to_json", &sph::sceneToJsonText,
           "Every key of the scene, defaults included, as JSON text.");

  m.def("box_drop_scene", &sph::boxDropScene, py::arg("particles"),
        "The benchmark scene of sph bench: about `particles` fluid particles dropped in a box.");
  m.def(
      "read_frame",
      [](const py::object& pathLike) {
        const std::string path = pathOf(pathLike);
        sph::ParticleFrame f;
        {
          py::gil_scoped_release release;
          f = sph::io::readFrame(path);
        }
        py::dict out = frameArrays(f);
        out["time"] = f.time;
        return out;
      },
      py::arg("path"),
      "A frame file (.vtp, .ply, .csv, as sph run writes them) as a dict of numpy arrays, "
      "with its time.");
  m.def(
      "_load_scene",
      [](const std::string& path, const std::vector<std::string>& overrides) {
        return sph::loadScene(path, overrides);
      },
      py::arg("path"), py::arg("overrides"));
  m.def("_parse_scene", &sph::parseScene, py::arg("text"), py::arg("source"), py::arg("overrides"));

  py::class_<sph::ObjectExchange, std::shared_ptr<sph::ObjectExchange>>(
      m, "ObjectExchange",
      "Objects of your own engine beside the fluid: publish their surface particles, take the "
      "fluid's forces on them (Simulation.attach_object_engine).")
      .def(py::init<std::size_t>(), py::arg("handle_count"),
           "Forces come back for handles 0 to handle_count - 1.")
      .def_property_readonly("handle_count", &sph::ObjectExchange::handleCount)
      .def("publish", &publish, py::arg("position"), py::arg("velocity"), py::arg("normal"),
           py::arg("radius"), py::arg("object"), py::arg("handle") = py::none(),
           py::arg("cut") = py::none(), py::arg("time") = 0.0,
           "The objects' surface particles for the fluid's next step: position, velocity and "
           "outward normal (n, 3), radius (n,) in m, object id (n,) from 0; handle (n,): the "
           "row each force comes back in (default: the particle's own row); cut (n,): 1 where "
           "the object is torn.")
      .def("take_forces", &takeForces,
           "(force, span): the mean force of the fluid on each handle, (handle_count, 3) in N, "
           "over the fluid steps since the last call, and the time they span in s.");

  py::class_<sph::Simulation>(m, "Simulation")
      .def(py::init([](const sph::Scene& scene, const std::string& backend, int threads) {
             sph::SimulationOptions options;
             options.backend = backendNamed(backend);
             options.threads = threads;
             return std::make_unique<sph::Simulation>(scene, options);
           }),
           py::arg("scene"), py::arg("backend") = "cpu", py::arg("threads") = 0,
           "A simulation of `scene` on `backend` (\"cpu\", \"cuda\" or \"auto\"); threads 0: "
           "every hardware thread. Results do not depend on the thread count.")
      .def(
          "step", [](sph::Simulation& s, double until) { s.step(until); },
          py::arg("until") = std::numeric_limits<double>::infinity(),
          py::call_guard<py::gil_scoped_release>(),
          "One time step, shortened so as not to pass `until`.")
      .def("attach_object_engine", &sph::Simulation::attachObjectEngine, py::arg("exchange"),
           "Couples the objects an ObjectExchange publishes to the fluid (once, before the "
           "first step).")
      .def("contain_fluid", &sph::Simulation::containFluid, py::arg("object"), py::arg("ids"),
           "The fluid particles `ids` are held by object `object` of the attached engine: one "
           "found outside it from now on counts as leaked (after attach_object_engine, before "
           "the first step).")
      .def(
          "objects",
          [](const sph::Simulation& s) {
            py::list out;
            for (const sph::ObjectStats& o : s.objectStats()) out.append(objectStats(o));
            return out;
          },
          "Each object's mass, centre, velocity and the fluid's force on it (N).")
      .def("advance_to", &sph::Simulation::advanceTo, py::arg("time"),
           py::call_guard<py::gil_scoped_release>(),
           "Steps until the simulated time reaches `time` (the last step is shortened to land "
           "on it).")
      .def_property_readonly("time", &sph::Simulation::time)
      .def_property_readonly("step_count", &sph::Simulation::stepCount)
      .def_property_readonly("last_dt", &sph::Simulation::lastDt)
      .def_property_readonly("fluid_count", &sph::Simulation::fluidCount)
      .def_property_readonly("removed_count", &sph::Simulation::removedCount)
      .def_property_readonly("leaked_count", &sph::Simulation::leakedCount)
      .def_property_readonly("backend", &sph::Simulation::backendName)
      .def_property_readonly(
          "calibration", &calibration,
          "The values derived from the scene (spacing, mass, speed of sound...).")
      .def("write_frame", &writeFrame, py::arg("path"), py::arg("format") = "vtp",
           py::arg("include_boundary") = true,
           "Writes the particles as sph run writes a frame (\"vtp\", \"ply\" or \"csv\"), "
           "atomically: a reader never sees half a file.")
      .def(
          "_timed_steps",
          [](sph::Simulation& s, int steps) {
            std::vector<double> ms;
            py::gil_scoped_release release;
            for (int k = 0; k < steps; ++k) {
              const auto start = std::chrono::steady_clock::now();
              s.step();
              ms.push_back(std::chrono::duration<double, std::milli>(
                               std::chrono::steady_clock::now() - start)
                               .count());
            }
            return ms;
          },
          py::arg("steps"),
          "Steps `steps` times from C++, timing each (ms): what scripts/bench-python sets "
          "Python's own step() against.")
      .def("stats", &stats, "The statistics of one row of stats.csv, with the objects'.")
      .def("particles", &particles, py::arg("include_boundary") = false,
           "Copies of the particles' arrays, ordered by id: id, position (n, 3), velocity "
           "(n, 3), density (kg/m³), pressure (Pa), kind (0 fluid, 1 wall, 2 object), "
           "object (-1 if none), surface (1 on the free surface).")
      .def(
          "view", [](py::object self) { return FluidArrays(self); },
          "The fluid's arrays without copying (see FluidArrays).")
      .def_property("live_parameters", &liveParameters, &setLiveParameters,
                    "The parameters that may change during a run; assign a dict of those to "
                    "change.");
}
