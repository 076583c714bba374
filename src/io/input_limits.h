// The resource limits of the readers: stated here, enforced before the work, documented in
// docs/limits.md. Every refusal is an InputError (CLI exit 2) naming the file, the field and the
// limit; a YAML position is given as "(yaml line L, column C)" where there is one.
#pragma once

#include <cstddef>

namespace linkproof {

/// Largest scene or claim file read, in bytes. Files are read with this cap (never to EOF), so
/// `/dev/zero` or a 10 MB file is refused after reading kMaxInputBytes + 1 bytes. A polygon of
/// kMaxSceneJoints joints with 30-digit coordinates fits easily.
inline constexpr std::size_t kMaxInputBytes = std::size_t{2} << 20;  // 2 MiB

/// Longest exact number in a scene, in characters of its text ("-123/456", "1.5e-3"). A number
/// of 200 digits is already far beyond any linkage; exponents are limited separately to
/// |e| <= 4000 (core/exact.h).
inline constexpr std::size_t kMaxNumberCharacters = 200;

}  // namespace linkproof
