// The `imasim` Python module's compiled part, `imasim._core` (docs/python.md): Session,
// HarvestCore and rollout. Every step runs with the GIL released; rollout steps its
// environments on threads of their own.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "harvest_core.hpp"
#include "metrics/output_file.hpp"
#include "py_session.hpp"
#include "scene/heart_placement.hpp"
#include "scene/mesh_file.hpp"
#include "scene/scene_file.hpp"
#include "surgery/events.hpp"
#include "tissue/tissue_world.hpp"

namespace py = pybind11;

namespace imasim::python {
namespace {

using FloatArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::array_t<double> vec3_array(const std::vector<Vec3>& x, std::uint32_t first,
                               std::uint32_t count) {
  py::array_t<double> out({py::ssize_t(count), py::ssize_t(3)});
  auto a = out.mutable_unchecked<2>();
  for (std::uint32_t k = 0; k < count; ++k)
    for (int c = 0; c < 3; ++c)
      a(k, c) = double(x[first + k][c]);
  return out;
}

py::array_t<double> vec3(const Vec3& v) {
  py::array_t<double> out(3);
  auto a = out.mutable_unchecked<1>();
  for (int c = 0; c < 3; ++c)
    a(c) = double(v[c]);
  return out;
}

py::array_t<double> pose_matrix(const Pose& p) {
  py::array_t<double> out({4, 4});
  auto a = out.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      a(r, c) = r < 3 ? (c < 3 ? double(p.rotation(r, c)) : double(p.translation[r]))
                      : (c == 3 ? 1.0 : 0.0);
  return out;
}

int hand_of(const py::object& hand) {
  if (py::isinstance<py::int_>(hand)) return hand.cast<int>();
  return hand_index(hand.cast<std::string>());
}

// A 4 x 4 pose, or a position (3) with an optional 3 x 3 rotation.
Pose pose_from(const FloatArray& position, const std::optional<FloatArray>& rotation) {
  Pose p;
  if (position.ndim() == 2 && position.shape(0) == 4 && position.shape(1) == 4) {
    auto a = position.unchecked<2>();
    for (int r = 0; r < 3; ++r) {
      p.translation[r] = Real(a(r, 3));
      for (int c = 0; c < 3; ++c)
        p.rotation(r, c) = Real(a(r, c));
    }
  } else if (position.ndim() == 1 && position.shape(0) == 3) {
    auto a = position.unchecked<1>();
    for (int r = 0; r < 3; ++r)
      p.translation[r] = Real(a(r));
    if (rotation) {
      if (rotation->ndim() != 2 || rotation->shape(0) != 3 || rotation->shape(1) != 3)
        throw std::invalid_argument("rotation: a 3 x 3 matrix");
      auto m = rotation->unchecked<2>();
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          p.rotation(r, c) = Real(m(r, c));
    }
  } else {
    throw std::invalid_argument("pose: a position of 3 values or a 4 x 4 matrix");
  }
  if (!p.translation.allFinite() || !p.rotation.allFinite())
    throw std::invalid_argument("pose: not finite");
  const Real orthogonality = (p.rotation.transpose() * p.rotation - Mat3::Identity()).norm();
  if (!(orthogonality < Real(1e-6)) || !(p.rotation.determinant() > 0))
    throw std::invalid_argument("pose: the rotation is not a rotation (orthonormal, det +1)");
  return p;
}

py::dict state_of(const PySession& py_session) {
  const session::SurgicalSession& s = py_session.session();
  const tissue::TissueWorld& w = s.scene.patch.world;
  const std::vector<Vec3>& x = w.state.particles.position;
  py::dict out;
  out["time"] = double(w.state.time);
  out["steps"] = py_session.steps();
  out["heart_phase"] = double(s.scene.heart.phase);
  out["heart_beating"] = s.scene.heart.playback.beating;
  py::dict positions;
  for (const tissue::MeshObject& m : w.meshes)
    positions[py::str(m.name)] = vec3_array(x, m.first_particle, m.particle_count);
  for (const tissue::StrandSet& set : w.strands)
    positions[py::str(set.name)] = vec3_array(x, set.first_particle, set.particle_count());
  out["positions"] = positions;
  const metrics::TrajectorySample sample = py_session.sample();
  py::dict tools;
  for (std::size_t k = 0; k < 2; ++k) {
    const metrics::ToolSample& t = sample.tools[k];
    const session::Station& st = s.stations[k];
    py::dict tool;
    tool["tip"] = vec3(t.tip);
    tool["pose"] = pose_matrix(st.pose);
    tool["device_pose"] = pose_matrix(st.device);
    tool["jaw_angle"] = double(t.jaw_angle);
    tool["force_normal"] = double(t.force_normal);
    tool["force_tangential"] = double(t.force_tangential);
    tool["force_thermal"] = double(t.force_thermal);
    tool["contact"] = surgery::to_string(t.contact);
    tool["contacts"] = st.contact.count;
    tool["device_lost"] = st.device_lost;
    tools[py::str(std::string(metrics::kToolNames[k]))] = tool;
  }
  out["tools"] = tools;
  out["pedal"] = surgery::to_string(sample.pedal);
  out["power_w"] = double(sample.power_w);
  out["heart_contacts"] = s.scene.heart.last_contacts;
  out["strands_cut"] = s.strands_cut;
  out["strands_torn"] = s.strands_torn;
  out["fascia_edges_cut"] = s.fascia_edges_cut;
  out["pedicle_divided"] = py_session.pedicle_divided();
  out["ima_injuries"] = s.events.count(surgery::EventKind::injury);
  return out;
}

py::list events_of(const PySession& py_session) {
  py::list out;
  for (const surgery::Event& e : py_session.session().events.events) {
    py::dict d;
    d["time"] = e.time;
    d["kind"] = surgery::to_string(e.kind);
    d["instrument"] = std::string(metrics::kToolNames[std::min<std::size_t>(e.instrument, 1)]);
    d["tissue"] = surgery::to_string(e.tissue);
    d["count"] = e.count;
    d["value"] = double(e.value);
    out.append(d);
  }
  return out;
}

surgery::PedalMode pedal_named(const std::string& mode) {
  if (mode == "cut") return surgery::PedalMode::cut;
  if (mode == "coag") return surgery::PedalMode::coag;
  if (mode == "off") return surgery::PedalMode::off;
  throw std::invalid_argument("pedal mode '" + mode + "': cut, coag or off");
}

py::tuple step_tuple(const HarvestStep& s) {
  py::array_t<float> obs{py::ssize_t(kObservationSize)};
  std::copy(s.observation.begin(), s.observation.end(), obs.mutable_data());
  py::dict info;
  info["pedicle_divided"] = s.pedicle_divided;
  info["ima_injuries"] = s.ima_injuries;
  info["max_force_n"] = s.max_force_n;
  return py::make_tuple(obs, s.reward, s.terminated, s.truncated, info);
}

// Steps each core through its actions (n_envs x T x kActionSize) on a thread of its own.
py::tuple rollout(std::vector<HarvestCore*> cores,
                  const py::array_t<float, py::array::c_style | py::array::forcecast>& actions) {
  if (actions.ndim() != 3 || std::size_t(actions.shape(0)) != cores.size() ||
      std::size_t(actions.shape(2)) != kActionSize)
    throw std::invalid_argument("actions: an array of n_envs x T x " + std::to_string(kActionSize));
  for (const HarvestCore* c : cores)
    if (c == nullptr) throw std::invalid_argument("rollout: an environment is None");
  // Each environment on one thread only: the same one twice would be stepped by two at once.
  std::vector<const HarvestCore*> sorted(cores.begin(), cores.end());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    throw std::invalid_argument("rollout: an environment is given twice");
  const std::size_t n = cores.size(), steps = std::size_t(actions.shape(1));
  std::vector<HarvestStep> results(n * steps);
  std::vector<std::string> errors(n);
  const float* data = actions.data();
  {
    py::gil_scoped_release release;
    std::vector<std::thread> threads;
    threads.reserve(n);
    for (std::size_t e = 0; e < n; ++e) {
      threads.emplace_back([&, e] {
        try {
          for (std::size_t t = 0; t < steps; ++t) {
            results[e * steps + t] =
                cores[e]->step(data + (e * steps + t) * kActionSize, kActionSize);
            const HarvestStep& r = results[e * steps + t];
            if (r.terminated || r.truncated) {
              for (std::size_t u = t + 1; u < steps; ++u)
                results[e * steps + u] = r;
              break;
            }
          }
        } catch (const std::exception& ex) {
          errors[e] = ex.what();
        }
      });
    }
    for (std::thread& t : threads)
      t.join();
  }
  for (std::size_t e = 0; e < n; ++e)
    if (!errors[e].empty())
      throw std::invalid_argument("environment " + std::to_string(e) + ": " + errors[e]);
  py::array_t<float> obs({py::ssize_t(n), py::ssize_t(steps), py::ssize_t(kObservationSize)});
  py::array_t<double> rewards({py::ssize_t(n), py::ssize_t(steps)});
  py::array_t<bool> terminated({py::ssize_t(n), py::ssize_t(steps)});
  py::array_t<bool> truncated({py::ssize_t(n), py::ssize_t(steps)});
  auto o = obs.mutable_unchecked<3>();
  auto r = rewards.mutable_unchecked<2>();
  auto te = terminated.mutable_unchecked<2>();
  auto tr = truncated.mutable_unchecked<2>();
  for (std::size_t e = 0; e < n; ++e) {
    for (std::size_t t = 0; t < steps; ++t) {
      const HarvestStep& s = results[e * steps + t];
      for (std::size_t k = 0; k < kObservationSize; ++k)
        o(e, t, k) = s.observation[k];
      // A finished episode repeats its last step's observation and earns nothing more.
      const bool repeated =
          t > 0 && (results[e * steps + t - 1].terminated || results[e * steps + t - 1].truncated);
      r(e, t) = repeated ? 0.0 : s.reward;
      te(e, t) = s.terminated;
      tr(e, t) = s.truncated;
    }
  }
  return py::make_tuple(obs, rewards, terminated, truncated);
}

}  // namespace
}  // namespace imasim::python

PYBIND11_MODULE(_core, m) {
  using namespace imasim;
  using namespace imasim::python;
  m.doc() = "imasim's compiled core: Session, HarvestCore, rollout (docs/python.md)";
  // Bad input is a ValueError naming what was refused (a scene file with its file, line and
  // key; a mesh; a heart that does not fit); a file that cannot be written is an OSError.
  static py::exception<std::invalid_argument> imasim_error(m, "ImasimError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const metrics::OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const scene::SceneFileError& e) {
      imasim_error(e.what());
    } catch (const scene::MeshFileError& e) {
      imasim_error(e.what());
    } catch (const scene::HeartPlacementError& e) {
      imasim_error(e.what());
    } catch (const std::invalid_argument& e) {
      imasim_error(e.what());
    }
  });

  py::class_<PySession>(m, "Session")
      .def(py::init([](std::optional<std::string> scene, std::optional<std::uint64_t> seed,
                       bool static_heart, int threads) {
             SessionOptions o;
             o.scene_file = scene.value_or("");
             o.patient_seed = seed;
             o.static_heart = static_heart;
             if (threads < 0 || threads > 64)
               throw std::invalid_argument("threads: 0 (all cores) to 64");
             o.threads = threads;
             py::gil_scoped_release release;
             return std::make_unique<PySession>(o);
           }),
           py::arg("scene") = py::none(), py::arg("seed") = py::none(), py::arg("static") = false,
           py::arg("threads") = 1)
      .def(
          "step",
          [](PySession& s, std::int64_t n) {
            if (n < 0) throw std::invalid_argument("step: n >= 0");
            py::gil_scoped_release release;
            return s.step(std::uint64_t(n));
          },
          py::arg("n") = 1)
      .def("state", &state_of)
      .def("events", &events_of)
      .def("state_hash", &PySession::state_hash)
      .def("record_input", &PySession::record_input, py::arg("path"))
      .def("stop_recording", &PySession::stop_recording)
      .def_property_readonly("dt", &PySession::dt)
      .def_property_readonly("steps", &PySession::steps)
      .def(
          "set_device_pose",
          [](PySession& s, const py::object& hand, const FloatArray& position,
             std::optional<FloatArray> rotation) {
            s.set_device_pose(hand_of(hand), pose_from(position, rotation));
          },
          py::arg("hand"), py::arg("pose"), py::arg("rotation") = py::none())
      .def(
          "grasp",
          [](PySession& s, bool close) {
            s.set_jaw(0, close ? surgery::JawCommand::close : surgery::JawCommand::open);
          },
          py::arg("close") = true)
      .def(
          "cut",
          [](PySession& s, bool on, const std::string& mode, double power_w) {
            s.set_pedal(on ? pedal_named(mode) : surgery::PedalMode::off, Real(power_w));
          },
          py::arg("on") = true, py::arg("mode") = "cut", py::arg("power_w") = 40.0)
      .def(
          "render",
          [](const PySession& s, int width, int height) {
            std::vector<std::uint8_t> rgb;
            {
              py::gil_scoped_release release;
              rgb = s.render(width, height);
            }
            py::array_t<std::uint8_t> out(
                {py::ssize_t(height), py::ssize_t(width), py::ssize_t(3)});
            std::copy(rgb.begin(), rgb.end(), out.mutable_data());
            return out;
          },
          py::arg("width") = 320, py::arg("height") = 240);

  py::class_<HarvestCore>(m, "HarvestCore")
      .def(py::init([](std::optional<std::string> scene, bool static_heart, double episode_s,
                       double power_w) {
             SessionOptions o;
             o.scene_file = scene.value_or("");
             o.static_heart = static_heart;
             return std::make_unique<HarvestCore>(o, episode_s, Real(power_w));
           }),
           py::arg("scene") = py::none(), py::arg("static") = false,
           py::arg("episode_seconds") = kDefaultEpisodeSeconds, py::arg("power_w") = 40.0)
      .def(
          "reset",
          [](HarvestCore& c, std::optional<std::uint64_t> seed) {
            HarvestStep s;
            {
              py::gil_scoped_release release;
              s = c.reset(seed);
            }
            return step_tuple(s);
          },
          py::arg("seed") = py::none())
      .def("step",
           [](HarvestCore& c,
              const py::array_t<float, py::array::c_style | py::array::forcecast>& action) {
             if (action.ndim() != 1)
               throw std::invalid_argument("an action is a vector of " +
                                           std::to_string(kActionSize));
             const std::vector<float> a(action.data(), action.data() + action.size());
             HarvestStep s;
             {
               py::gil_scoped_release release;
               s = c.step(a.data(), a.size());
             }
             return step_tuple(s);
           })
      .def_property_readonly(
          "session", [](HarvestCore& c) -> PySession& { return c.session(); },
          py::return_value_policy::reference_internal);

  m.def("rollout", &rollout, py::arg("cores"), py::arg("actions"));
  m.attr("ACTION_SIZE") = kActionSize;
  m.attr("OBSERVATION_SIZE") = kObservationSize;
  m.attr("PHYSICS_STEPS_PER_ACTION") = kPhysicsStepsPerAction;
  m.attr("MAX_TOOL_SPEED") = double(kMaxToolSpeed);
  m.attr("OBSERVATION_NAMES") = observation_names();
  m.attr("REWARD") =
      py::dict(py::arg("progress") = kProgressReward, py::arg("injury") = kInjuryPenalty,
               py::arg("force_per_n") = kForcePenaltyPerN, py::arg("time") = kTimePenalty);
}
