#include <whiskermap/inference/SamplerParams.h>

#include <string>

namespace whiskermap::inference
{
SamplerParams SamplerParams::fromIni(core::IniSection& sec)
{
	SamplerParams p;
	p.r1 = sec.number("r1", 0, 1);
	p.r2 = sec.number("r2", p.r1, 1);
	p.r3 = sec.number("r3", p.r2, 1);
	p.r4 = sec.number("r4", p.r3, 1);
	const double beta0 = sec.number("beta_start", 1e-6, 1e6);
	const double beta1 = sec.number("beta_end", beta0, 1e6);
	p.schedule = AnnealingSchedule::geometric(beta0, beta1, sec.integer("temperatures", 1, 10000));
	p.sweeps_per_temperature = static_cast<int>(sec.integer("sweeps_per_temperature", 1, 1000));
	p.coldest_sweeps = static_cast<int>(sec.integer("coldest_sweeps", 1, 1000));
	p.polish_sweeps = static_cast<int>(sec.integer("polish_sweeps", 0, 1000));
	p.existing_leg_probability = sec.number("existing_leg_probability", 0, 1);
	p.merge_probability = sec.number("merge_probability", 0, 1);
	p.leg_position_noise = sec.number("leg_position_noise", 0, 1);
	p.leg_angle_noise = sec.number("leg_angle_noise", 0, 1);
	const std::string rule = sec.text("acceptance", "gibbs");
	if (rule == "reversible_jump")
		p.acceptance = AcceptanceRule::ReversibleJump;
	else if (rule != "gibbs")
		sec.fail("acceptance", "must be gibbs or reversible_jump, not '" + rule + "'");
	const std::string proposals = sec.text("proposals", "data_driven");
	if (proposals == "broad")
		p.proposals = Proposals::Broad;
	else if (proposals != "data_driven")
		sec.fail("proposals", "must be data_driven or broad, not '" + proposals + "'");
	p.posterior_steps = sec.integer("posterior_steps", 0, 0, 100000000);
	sec.finish();
	return p;
}
}  // namespace whiskermap::inference
