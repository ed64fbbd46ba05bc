#pragma once
#include <cmath>
#include <cstddef>

namespace whiskermap::eval
{
/** Object class and size figures of a map whose objects carry a class (doc/evaluation.md):
 *  the class accuracy over a matching that ignores the class (same gates), and the mean
 *  absolute dimension errors over the class-aware matching. NaN when nothing was matched. */
struct ClassFigures
{
	size_t matched_any_class = 0;  ///< pairs of the class-blind matching
	double class_accuracy = NAN;  ///< fraction of them whose classes agree
	double length_err_m = NAN;  ///< mean |estimated - true| leg-centre spacing along x
	double width_err_m = NAN;  ///< ... along y
	double leg_width_err_m = NAN;  ///< ... of the leg side
	double leg_width_bias_m = NAN;  ///< mean estimated - true leg side (signed: a bias shows)
	double texture_err = NAN;  ///< ... of the leg texture
};
}  // namespace whiskermap::eval
