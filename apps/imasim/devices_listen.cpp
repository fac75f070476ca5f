#include "devices_listen.hpp"

#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "console/console_settings_use.hpp"
#include "devices/igtl_link.hpp"
#include "interrupt.hpp"
#include "report.hpp"

namespace imasim::cli {

namespace {

// What a message of this name and type becomes under the scene's mapping.
std::string meaning(const devices::IgtlNames& n, const std::string& name, const std::string& type) {
  if (type == "TRANSFORM") {
    if (name == n.left_pose) return "left hand's pose (devices.left_hand)";
    if (name == n.right_pose) return "right hand's pose (devices.right_hand)";
    if (name == n.left_tool) return "left tool's pose (devices.left_tool)";
    if (name == n.right_tool) return "right tool's pose (devices.right_tool)";
    return "refused: no hand is mapped to it (set devices.left_hand or devices.right_hand to \"" +
           name + "\")";
  }
  if (type == "SENSOR") {
    if (name == n.left_buttons) return "left hand's buttons (devices.left_buttons)";
    if (name == n.right_buttons) return "right hand's buttons (devices.right_buttons)";
    if (name == n.pedal) return "the pedal (devices.pedal)";
    return "refused: not mapped (devices.left_buttons, devices.right_buttons or devices.pedal)";
  }
  return "refused: imasim reads TRANSFORM and SENSOR only";
}

}  // namespace

int listen_for_devices(const scene::ConsoleSettings& settings, const ListenOptions& o) {
  devices::IgtlLinkConfig config = console::igtl_device_config(settings).link;
  if (o.port) config.port = *o.port;
  std::optional<devices::IgtlLink> link;
  try {
    link.emplace(config);
  } catch (const devices::IgtlLinkError& e) {
    std::cerr << "devices --listen: " << e.what() << '\n';
    return 2;
  }
  install_interrupt_handlers();
  std::cerr << "listening for OpenIGTLink on " << config.address << ":" << link->port() << " for "
            << o.seconds << " s (Ctrl-C ends it)\n";
  devices::ConsoleInput input;
  std::size_t told = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.seconds);
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() < end && interrupt_signal() == 0) {
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    link->poll(input, now);
    const devices::IgtlCounters& c = link->counters();
    for (; told < c.arrived; ++told) {  // each new name and type as it first arrives
      const devices::IgtlArrival& a = c.arrivals[told];
      if (!o.json)
        std::cout << "arriving: " << a.type.data() << " \""
                  << devices::igtl_printable_name(a.name.data()) << "\" -> "
                  << meaning(config.names, a.name.data(), a.type.data()) << std::endl;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const devices::IgtlCounters& c = link->counters();
  nlohmann::ordered_json arrivals = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < c.arrived; ++k) {
    const devices::IgtlArrival& a = c.arrivals[k];
    arrivals.push_back({{"name", devices::igtl_printable_name(a.name.data())},
                        {"type", a.type.data()},
                        {"messages", a.messages},
                        {"accepted", a.accepted},
                        {"becomes", meaning(config.names, a.name.data(), a.type.data())}});
  }
  nlohmann::ordered_json refused = nlohmann::ordered_json::object();
  for (std::size_t r = 0; r < devices::kIgtlRefusals; ++r)
    if (c.refused[r] > 0)
      refused[devices::igtl_refusal_name(devices::IgtlRefusal(r))] = c.refused[r];
  nlohmann::ordered_json out;
  out["address"] = config.address;
  out["port"] = link->port();
  out["arrivals"] = arrivals;
  out["refused"] = refused;
  out["peers_seen"] = link->peers_seen();
  out["peers_dropped"] = link->peers_dropped();
  out["peers_turned_away"] = link->peers_turned_away();
  out["interrupted"] = interrupt_signal() != 0;
  if (o.json) return print_report(out, true) ? 0 : 4;
  std::cout << "heard " << c.arrived << " device name(s) from " << link->peers_seen() << " peer(s)";
  if (c.arrived == 0) std::cout << ": nothing arrived (is the tracker sending to this port?)";
  std::cout << '\n';
  for (const auto& a : arrivals)
    std::cout << "  " << a["type"].get<std::string>() << " \"" << a["name"].get<std::string>()
              << "\": " << a["messages"] << " messages, " << a["accepted"] << " accepted -> "
              << a["becomes"].get<std::string>() << '\n';
  for (const auto& [reason, n] : refused.items())
    std::cout << "  refused " << reason << ": " << n << '\n';
  return 0;
}

}  // namespace imasim::cli
