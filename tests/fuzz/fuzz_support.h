#pragma once
// What the fuzz targets share: the readers under test take a path (the Biip reader maps its
// file), so each input is written to one scratch file per process first; and samples that a
// reader accepted are pushed on through what a quality map and the import command do with them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/base/trajectory.h"

namespace isurface::fuzz {

// Writes the input to this process's scratch file (`suffix` names its kind) and returns its path.
const std::string& writeScratch(const std::uint8_t* data, std::size_t size, const char* suffix);

// Splits passes, builds the surface and colours it by the quantities that read every sample
// and neighbour: whatever damaged values a reader lets through (NaN, huge or backward times,
// odd line numbers) end up there.
void exerciseSamples(const Trajectory& samples);

// Writes the samples as the import command does and reads the dump back.
void roundTripThroughBiip(const Trajectory& samples);

// Bad input must end in InputError and nothing else: any other exception escapes the target
// and the fuzzer reports it as a crash.
template <typename Body>
void expectOnlyInputErrors(Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  }
}

}  // namespace isurface::fuzz
