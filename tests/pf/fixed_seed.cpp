// Test-only LD_PRELOAD shim: makes stock pf-localization reproducible.
//
// MRPT 2.5.8's pf-localization seeds the global random generator with
// getRandomGenerator().randomize() (no argument: std::random_device) and has no seed option.
// Preloading this library replaces that one member function: it seeds from
// $WHISKERMAP_PF_SEED (default 1) instead. Everything else (initial particles, motion
// samples, resampling) still runs MRPT's own code and generator. Interposition works because
// libmrpt-apps calls CRandomGenerator::randomize() through the PLT of libmrpt-random; if a
// future MRPT inlined it, runs would merely stop being reproducible (the test's thresholds
// hold for every seed measured: doc/pf-localization.md).
#include <mrpt/random/RandomGenerators.h>

#include <cstdint>
#include <cstdlib>

void mrpt::random::CRandomGenerator::randomize()
{
	const char* s = std::getenv("WHISKERMAP_PF_SEED");
	randomize(static_cast<uint32_t>(s && *s ? std::strtoul(s, nullptr, 10) : 1UL));
}
