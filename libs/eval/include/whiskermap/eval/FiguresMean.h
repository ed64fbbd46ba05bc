#pragma once
#include <whiskermap/eval/Figures.h>

#include <cstddef>

namespace whiskermap::eval
{
/** Figures::mean accumulated one item at a time (constant memory, for streaming runs). */
class FiguresMean
{
   public:
	void add(const Figures& f);
	Figures result() const;

   private:
	Figures m_sum{0, 0, 0, 0, NAN, NAN, 0};
	double m_rmse = 0, m_yaw = 0, m_aligned = 0;
	size_t m_n = 0, m_defined = 0, m_alignedDefined = 0;
};
}  // namespace whiskermap::eval
