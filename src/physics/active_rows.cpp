#include "physics/active_rows.hpp"

#include <algorithm>
#include <span>

#include "physics/state.hpp"

namespace imasim::physics {

namespace {

// The rows of `band` with a touched particle, in projection order.
template <class Row>
std::size_t collect(const ColouredStore<Row>& store, std::uint32_t band,
                    const std::vector<std::uint8_t>& touched, std::vector<RowRef>& out) {
  using Store = ColouredStore<Row>;
  const auto groups = store.groups();
  std::size_t n = 0;
  auto visit = [&](std::uint32_t g) {
    const auto& rows = groups[g].rows;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      bool any = false;
      for (std::uint32_t p : rows[k].particles())
        any = any || touched[p] != 0;
      if (any) out[n++] = {g, static_cast<std::uint32_t>(k)};
    }
  };
  for (std::uint32_t g = store.band_first(band); g < store.band_end(band); ++g)
    visit(g);
  visit(Store::overflow_group(band));
  return n;
}

// The rows of `band` in a sequence ordered band 0 first, band 1 from `split`.
template <class Row>
std::span<const Row> of_band(const std::vector<Row>& rows, std::size_t split, std::uint32_t band) {
  return band == 0 ? std::span<const Row>(rows.data(), split)
                   : std::span<const Row>(rows.data() + split, rows.size() - split);
}

}  // namespace

void prepare_active_rows(const State& state, ActiveRows& active) {
  if (active.touched.size() < state.particles.size()) active.touched.resize(state.particles.size());
  const std::size_t d = state.constraints.distance.size();
  const std::size_t a = state.constraints.attachment.size();
  if (active.distance.size() < d) active.distance.resize(d);
  if (active.attachment.size() < a) active.attachment.resize(a);
}

void find_active_rows(State& state, std::uint32_t band, ActiveRows& active) {
  active.distance_count = active.attachment_count = 0;
  const StepScratch& s = state.scratch;
  const auto contacts = of_band(state.contacts.rows, s.contact_split, band);
  const auto held = of_band(state.body_attachments, s.body_attachment_split, band);
  const auto supports = of_band(state.supports, s.support_split, band);
  if (contacts.empty() && held.empty() && supports.empty()) return;  // the band at rest
  std::fill(active.touched.begin(), active.touched.end(), std::uint8_t(0));
  for (const ContactRow& c : contacts)
    active.touched[c.particle] = 1;
  for (const BodyAttachmentRow& r : held)
    active.touched[r.particle] = 1;
  for (const SupportRow& r : supports)
    active.touched[r.particle] = 1;
  active.distance_count =
      collect(state.constraints.distance, band, active.touched, active.distance);
  active.attachment_count =
      collect(state.constraints.attachment, band, active.touched, active.attachment);
}

}  // namespace imasim::physics
