#pragma once
// What the interpreter suites share: interpreting a text, its program and its first error.
#include <gtest/gtest.h>

#include <string>

#include "isurface/gcode/gcode_interpreter.h"

namespace isurface::gcodetest {

inline InterpretResult run(const std::string& text, InterpreterOptions options = {}) {
  return interpretGcode(text, "t.ngc", options);
}

// The program of a text that must interpret without errors.
inline Program interpret(const std::string& text) {
  const InterpretResult r = interpretGcode(text, "test.ngc");
  EXPECT_TRUE(r.ok());
  return r.program;
}

inline std::string firstError(const std::string& text) {
  const InterpretResult r = run(text);
  return r.errors.empty() ? std::string("<no error>") : r.errors[0].str();
}

inline void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-9) {
  EXPECT_NEAR(a.x(), b.x(), tol);
  EXPECT_NEAR(a.y(), b.y(), tol);
  EXPECT_NEAR(a.z(), b.z(), tol);
}

}  // namespace isurface::gcodetest
