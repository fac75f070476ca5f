#pragma once
// A linked GLSL program; compile and link errors become exceptions carrying the driver's log.
#include <string>

namespace imasim::render {

class GlProgram {
 public:
  GlProgram(const std::string& vertex_source, const std::string& fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  unsigned id() const { return id_; }
  int uniform(const char* name) const;

 private:
  unsigned id_ = 0;
};

}  // namespace imasim::render
