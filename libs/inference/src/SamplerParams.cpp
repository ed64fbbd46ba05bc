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

bool SamplerParams::operator==(const SamplerParams& o) const
{
	return r1 == o.r1 && r2 == o.r2 && r3 == o.r3 && r4 == o.r4 && schedule.betas() == o.schedule.betas() &&
		   sweeps_per_temperature == o.sweeps_per_temperature && coldest_sweeps == o.coldest_sweeps &&
		   polish_sweeps == o.polish_sweeps && existing_leg_probability == o.existing_leg_probability &&
		   merge_probability == o.merge_probability && leg_position_noise == o.leg_position_noise &&
		   leg_angle_noise == o.leg_angle_noise && acceptance == o.acceptance && proposals == o.proposals &&
		   posterior_steps == o.posterior_steps;
}
}  // namespace whiskermap::inference
