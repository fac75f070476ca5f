// No heap allocation inside a step once the scene is built. This binary replaces the C
// allocator (which operator new uses) with counting wrappers around glibc's.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdlib>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
}
}  // namespace

extern "C" {
void* malloc(std::size_t n) {
  count();
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  count();
  return __libc_realloc(p, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) {
  count();
  return __libc_memalign(alignment, n);
}
void* memalign(std::size_t alignment, std::size_t n) {
  count();
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  count();
  void* p = __libc_memalign(alignment, n);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
void free(void* p) {
  __libc_free(p);
}
}

namespace imasim {
namespace {

long allocations_during_steps(int threads, physics::Response response) {
  scene::ClothParams p;
  p.n = 100;  // colour groups large enough to be split across threads
  p.response = response;
  p.substeps = 2;
  p.linear_damping = 0.03;
  scene::ClothScene s = scene::make_cloth_scene(p);
  physics::Executor exec(threads);
  for (int n = 0; n < 5; ++n)
    EXPECT_TRUE(physics::step(s.model, s.state, exec).ok());  // warm-up
  g_allocations = 0;
  g_counting = true;
  for (int n = 0; n < 20; ++n)
    EXPECT_TRUE(physics::step(s.model, s.state, exec).ok());
  g_counting = false;
  return g_allocations.load();
}

TEST(NoAllocation, CountingWorks) {
  g_allocations = 0;
  g_counting = true;
  auto* p = new int(3);
  g_counting = false;
  delete p;
  EXPECT_EQ(g_allocations.load(), 1);
}

TEST(NoAllocation, StepDoesNotAllocateOnOneThread) {
  EXPECT_EQ(allocations_during_steps(1, physics::Response::pbd), 0);
  EXPECT_EQ(allocations_during_steps(1, physics::Response::xpbd), 0);
}

TEST(NoAllocation, StepDoesNotAllocateOnTwoThreads) {
  EXPECT_EQ(allocations_during_steps(2, physics::Response::pbd), 0);
}

TEST(NoAllocation, TissueStepDoesNotAllocate) {
  for (const int threads : {1, 2}) {
    tissue::ThoracicPatch patch =
        tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
    physics::Executor exec(threads);
    for (int n = 0; n < 5; ++n)
      EXPECT_TRUE(tissue::step_tissue(patch.world, exec).ok());
    g_allocations = 0;
    g_counting = true;
    for (int n = 0; n < 20; ++n)
      EXPECT_TRUE(tissue::step_tissue(patch.world, exec).ok());
    g_counting = false;
    EXPECT_EQ(g_allocations.load(), 0) << threads << " threads";
  }
}

TEST(NoAllocation, ThoraxSceneStepDoesNotAllocate) {
  for (const int threads : {1, 2}) {
    scene::ThoraxScene s = scene::make_thorax_scene(scene::default_thorax_scene_params());
    physics::Executor exec(threads);
    for (int n = 0; n < 5; ++n)
      EXPECT_TRUE(scene::step_thorax_scene(s, exec).ok());
    g_allocations = 0;
    g_counting = true;
    for (int n = 0; n < 40; ++n)
      EXPECT_TRUE(scene::step_thorax_scene(s, exec).ok());
    g_counting = false;
    EXPECT_EQ(g_allocations.load(), 0) << threads << " threads";
  }
}

}  // namespace
}  // namespace imasim
