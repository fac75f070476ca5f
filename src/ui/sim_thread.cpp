#include "ui/sim_thread.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "console/console_settings_use.hpp"
#include "metrics/output_file.hpp"
#include "render/frame_of_session.hpp"

namespace imasim::ui {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Behind real time by more than this, the pacing starts afresh instead of running steps back
// to back to catch up (a machine slower than real time just runs slower; unit: s).
constexpr double kMaxLag_s = 0.1;

}  // namespace

const char* to_string(SimState s) {
  switch (s) {
    case SimState::starting:
      return "starting";
    case SimState::running:
      return "running";
    case SimState::paused:
      return "paused";
    case SimState::restarting:
      return "restarting";
    case SimState::finished:
      return "finished";
    case SimState::failed:
      return "failed";
  }
  return "?";
}

SimThread::SimThread(const SimConfig& config, std::unique_ptr<runner::InputSource> input)
    : config_(config), input_(std::move(input)), exec_(config.threads) {
  if (!input_) throw std::invalid_argument("the window's physics thread needs an input source");
  config_.steps_per_frame = std::max(1, config_.steps_per_frame);
  beating_next_.store(config_.scene.playback.beating);
  build_session();
}

SimThread::~SimThread() {
  stop();
}

void SimThread::build_session() {
  config_.scene.playback.beating = beating_next_.load();
  session_.reset();  // the old one's memory first: two thoraxes need not fit at once
  score_.reset();
  session_ = std::make_unique<session::SurgicalSession>(
      session::make_surgical_session(config_.scene, config_.session));
  score_ =
      std::make_unique<SessionScore>(*session_, console::force_model_params(config_.scene.console),
                                     config_.scene.patch.vessel.radius);
  if (!runner_) {
    runner_ = std::make_unique<runner::SessionRunner>(
        *session_, *input_, exec_,
        config_.realtime ? runner::Pacing::real_time : runner::Pacing::as_fast_as_possible);
    runner_->set_max_lag(kMaxLag_s);
    runner_->observe(*this);
    runner_->adjust_input([this](session::SessionInput& in) {
      if (const float optics = optics_.load(); optics >= 0) in.camera.optics = Real(optics);
    });
  } else {
    runner_->restart(*session_);
  }
  score_->sample(*session_);  // the state before the first step
  ++numbers_out_.session;
  numbers_out_.hands = {};
  numbers_out_.ima_injuries = numbers_out_.grasps = 0;
  numbers_out_.contacts_begun = {};
  numbers_out_.running_s = 0;
  events_tallied_ = 0;
}

void SimThread::start() {
  if (thread_.joinable() || stopped_) return;
  thread_ = std::thread([this] { run(); });
}

void SimThread::stop() {
  quit_.store(true);
  if (thread_.joinable()) thread_.join();
  if (!stopped_ && input_) input_->stop();
  if (!stopped_ && score_ && score_->recording()) {
    try {
      score_->stop_recording();
    } catch (const metrics::OutputError&) {
      // Nothing to tell after the window closed: the recording ends where its last flush did.
    }
  }
  stopped_ = true;
}

std::optional<ScoreCard> SimThread::score_card() const {
  std::lock_guard<std::mutex> lock(card_mutex_);
  return card_;
}

void SimThread::note(const std::string& text) {
  auto& m = numbers_out_.message;
  const std::size_t n = std::min(text.size(), m.size() - 1);
  std::memcpy(m.data(), text.data(), n);
  m[n] = '\0';
}

std::string SimThread::next_record_path() {
  ++recordings_;
  const std::string base = config_.record_path.empty() ? "imasim-window.csv" : config_.record_path;
  if (recordings_ == 1) return base;
  const bool csv = base.size() > 4 && base.compare(base.size() - 4, 4, ".csv") == 0;
  const std::string stem = csv ? base.substr(0, base.size() - 4) : base;
  return stem + "-" + std::to_string(recordings_) + ".csv";
}

void SimThread::take_commands() {
  if (restart_.exchange(false)) {
    if (score_ && score_->recording()) {
      try {
        score_->stop_recording();
      } catch (const metrics::OutputError& e) {
        note(e.what());
      }
    }
    record_.store(false);
    state_ = SimState::restarting;
    publish(false);
    try {
      build_session();  // the runner restarts the input with it
      state_ = paused_.load() ? SimState::paused : SimState::running;
      note(beating_next_.load() ? "new session: dynamic heart" : "new session: static heart");
    } catch (const std::exception& e) {
      session_.reset();
      state_ = SimState::failed;
      note(std::string("cannot build the scene: ") + e.what());
    }
    if (session_) publish(true);
    return;
  }
  if (!session_) return;
  if (end_.exchange(false) && (state_ == SimState::running || state_ == SimState::paused))
    finish_session("session ended: score card ready");
  if (state_ == SimState::running && paused_.load()) state_ = SimState::paused;
  if (state_ == SimState::paused && !paused_.load()) state_ = SimState::running;
  if (record_.load() != score_->recording() && state_ != SimState::finished) {
    try {
      if (record_.load()) {
        const std::string path = next_record_path();
        score_->start_recording(path, config_.scene_name, session_->scene.heart.playback.beating);
        note("recording to " + path);
      } else {
        score_->stop_recording();
        note("recording stopped");
      }
    } catch (const metrics::OutputError& e) {
      record_.store(false);
      note(e.what());
    }
  }
}

void SimThread::finish_session(const char* why) {
  state_ = SimState::finished;
  if (score_->recording()) {
    try {
      score_->stop_recording();
    } catch (const metrics::OutputError& e) {
      note(e.what());
    }
  }
  record_.store(false);
  {
    std::lock_guard<std::mutex> lock(card_mutex_);
    card_ = score_->score_card(*session_);
  }
  note(why);
  publish(true);
  // Last: finished() turns true only once the final numbers and frame are out.
  card_generation_.fetch_add(1);
}

void SimThread::step_once() {
  const runner::StepOutcome out = runner_->step();
  last_step_ms_ = out.step_ms;
  if (!out.result.ok()) {
    state_ = SimState::failed;
    note(std::string("the step was refused (") + physics::to_string(out.result.status) +
         "): restart with F5");
    publish(true);
    return;
  }
  if (steps() % std::uint64_t(config_.steps_per_frame) == 0) publish(true);
  if (config_.end_s > 0 && session_->scene.patch.world.state.time >= config_.end_s - 1e-9)
    finish_session("reached the end time: score card ready");
}

void SimThread::after_step(const session::SurgicalSession& s, const runner::StepRecord& record) {
  numbers_out_.power_w = record.input.right.power;
  numbers_out_.optics_rad = record.input.camera.optics;
  // A recording that cannot be written stops; the session goes on.
  try {
    score_->sample(s);
  } catch (const metrics::OutputError& e) {
    record_.store(false);
    try {
      score_->stop_recording();
    } catch (const metrics::OutputError&) {
    }
    note(e.what());
  }
}

void SimThread::publish(bool frame) {
  LiveNumbers& n = numbers_out_;
  n.state = state_;
  n.beating_next = beating_next_.load();
  n.recording = score_ && score_->recording();
  n.recorded_rows = score_ ? score_->recorded_rows() : 0;
  n.step_ms = last_step_ms_;
  if (session_) {
    const session::SurgicalSession& s = *session_;
    if (frame) {
      render::frame_of_session(s, frames_.back());
      frames_.publish();
    }
    const tissue::TissueWorld& w = s.scene.patch.world;
    const double wall = seconds_since(born_);
    if (wall - rate_wall_s_ >= 0.5 || w.state.time < rate_sim_s_) {
      n.realtime_factor = wall - rate_wall_s_ > 0 && state_ == SimState::running
                              ? (w.state.time - rate_sim_s_) / (wall - rate_wall_s_)
                              : 0;
      rate_wall_s_ = wall;
      rate_sim_s_ = w.state.time;
    }
    n.time_s = w.state.time;
    n.steps = steps();
    n.beating = s.scene.heart.playback.beating;
    n.heart_rate_bpm = s.scene.heart.playback.heart_rate_bpm;
    n.heart_phase = s.scene.heart.phase;
    const bool new_row = frame && state_ == SimState::running && !score_->rows().empty();
    for (std::size_t k = 0; k < 2; ++k) {
      const session::Station& st = s.stations[k];
      HandNumbers& h = n.hands[k];
      h.jaw_angle_rad = st.state.jaw_angle;
      h.clutch = st.arm_state.clutched;
      h.blocked_by_heart = st.blocked_by_heart;
      h.blocked_by_wall = st.blocked_by_wall;
      h.device_lost = st.device_lost;
      if (!score_->rows().empty()) {
        const metrics::ToolSample& t = score_->rows().back().tools[k];
        h.force_normal = t.force_normal;
        h.force_tangential = t.force_tangential;
        h.force_thermal = t.force_thermal;
        h.contact = t.contact;
      }
      if (new_row) {
        const std::array<float, 3> f = {float(h.force_normal), float(h.force_tangential),
                                        float(h.force_thermal)};
        for (std::size_t c = 0; c < 3; ++c) {
          auto& line = h.history[c];
          std::copy(line.begin() + 1, line.end(), line.begin());
          line.back() = f[c];
        }
      }
    }
    n.pedal = s.stations[1].pedal;
    n.device_refusals = input_->refused_total();
    if (const std::optional<console::DeviceTally> t = input_->device_tally()) {
      n.has_device_tally = true;
      n.device_tally = *t;
    }
    n.events = s.events.events.size();
    n.fascia_edges_cut = s.fascia_edges_cut;
    n.strands_cut = s.strands_cut;
    n.strands_torn = s.strands_torn;
    n.strands_total = w.strands[s.scene.patch.ima_fat].strand_count +
                      w.strands[s.scene.patch.fascia_fat].strand_count;
    // Only the events since the last publication: a long session has many.
    for (; events_tallied_ < s.events.events.size(); ++events_tallied_) {
      const surgery::Event& e = s.events.events[events_tallied_];
      n.ima_injuries += e.kind == surgery::EventKind::injury ? 1 : 0;
      n.grasps += e.kind == surgery::EventKind::grasp ? 1 : 0;
      n.devices_lost += e.kind == surgery::EventKind::device_lost ? 1 : 0;
      if (e.kind == surgery::EventKind::contact_begin) ++n.contacts_begun[std::size_t(e.tissue)];
    }
    n.instrument_collisions = std::uint32_t(score_->instrument_collisions());
    n.heart_contacts = scene::heart_contacts(s.scene);
    n.sai_available = score_->sai_available();
    n.sai = {score_->sai(0), score_->sai(1)};
  }
  numbers_.publish(n);
}

void SimThread::run() {
  publish(true);
  state_ = paused_.load() ? SimState::paused : SimState::running;
  Clock::time_point lap = Clock::now();
  while (!quit_.load()) {
    // Wall-clock time spent running, for the session's overall real-time factor.
    const Clock::time_point now_lap = Clock::now();
    if (state_ == SimState::running)
      numbers_out_.running_s += std::chrono::duration<double>(now_lap - lap).count();
    lap = now_lap;
    take_commands();
    if (state_ != SimState::running) {
      publish(false);
      std::this_thread::sleep_for(std::chrono::milliseconds(15));
      if (runner_) runner_->repace();
      continue;
    }
    step_once();
  }
}

}  // namespace imasim::ui
