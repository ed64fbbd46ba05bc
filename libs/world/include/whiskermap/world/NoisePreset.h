#pragma once
#include <whiskermap/obs/TSensorNoise.h>

#include <string>

namespace whiskermap::world
{
/** Sensor noise levels from a noise .ini ([noise] sigma_r, sigma_phi_deg, sigma_tau).
 *  Shipped presets live in config/noise/: noiseless, default, very-noisy. */
struct NoisePreset
{
	/** `nameOrPath`: a preset name or a path to a noise .ini. */
	static obs::TSensorNoise load(const std::string& nameOrPath);
};
}  // namespace whiskermap::world
