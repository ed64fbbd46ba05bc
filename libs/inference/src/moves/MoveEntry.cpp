#include <whiskermap/inference/moves/MoveEntry.h>

namespace whiskermap::inference::moves
{
bool MoveEntry::offered(const MoveContext& ctx, double u) const
{
	const SamplerParams& p = ctx.sp;
	if (slot == Slot::PolishLastSweep) return ctx.greedy() && ctx.searchPoses;
	if (slot == Slot::PolishButLast) return ctx.greedy() && !ctx.searchPoses;
	if (slot == Slot::Always || ctx.greedy()) return true;
	switch (slot)
	{
		case Slot::Death: return u < p.r1;
		case Slot::NewParent: return u >= p.r1 && u < p.r2;
		case Slot::Child: return u >= p.r2 && u < p.r3;
		case Slot::Refit: return u >= p.r3 && u < p.r4;
		default: return u >= p.r4;
	}
}
}  // namespace whiskermap::inference::moves
