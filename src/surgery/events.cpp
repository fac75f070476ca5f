#include "surgery/events.hpp"

namespace imasim::surgery {

const char* to_string(EventKind kind) {
  switch (kind) {
    case EventKind::grasp:
      return "grasp";
    case EventKind::release:
      return "release";
    case EventKind::fascia_cut:
      return "fascia_cut";
    case EventKind::strand_cut:
      return "strand_cut";
    case EventKind::cautery_on:
      return "cautery_on";
    case EventKind::cautery_off:
      return "cautery_off";
    case EventKind::contact_begin:
      return "contact_begin";
    case EventKind::contact_end:
      return "contact_end";
    case EventKind::injury:
      return "injury";
    case EventKind::cut_refused:
      return "cut_refused";
    case EventKind::fragment_vaporised:
      return "fragment_vaporised";
    case EventKind::strand_torn:
      return "strand_torn";
    case EventKind::device_lost:
      return "device_lost";
    case EventKind::device_restored:
      return "device_restored";
  }
  return "unknown";
}

const char* to_string(Tissue tissue) {
  switch (tissue) {
    case Tissue::none:
      return "none";
    case Tissue::fascia:
      return "fascia";
    case Tissue::ima:
      return "ima";
    case Tissue::fat:
      return "fat";
    case Tissue::heart:
      return "heart";
    case Tissue::chest_wall:
      return "chest_wall";
  }
  return "unknown";
}

}  // namespace imasim::surgery
