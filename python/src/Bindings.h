#pragma once
// The pieces of the whiskermap Python module (module.cpp assembles them). Bindings only:
// every function calls the C++ libraries and converts arguments and results.
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <filesystem>
#include <vector>

namespace whiskermap::python
{
namespace py = pybind11;

/** A file path argument: a str or any os.PathLike (pathlib.Path). */
using Path = std::filesystem::path;

/** A planar pose as Python sees it: (x, y, yaw), metres and radians. */
using Pose = std::array<double, 3>;

inline mrpt::poses::CPose2D toPose2D(const Pose& p) { return {p[0], p[1], p[2]}; }
inline Pose fromPose2D(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
/** A 3-D pose in the plane (x, y, yaw): how the apps make robot and sensor poses. */
inline mrpt::poses::CPose3D toPose3D(const Pose& p) { return {p[0], p[1], 0, p[2], 0, 0}; }
inline Pose fromPose3D(const mrpt::poses::CPose3D& p) { return {p.x(), p.y(), p.yaw()}; }

/** Poses as an (n, 3) float64 array (x, y, yaw per row), and back. */
py::array_t<double> posesToArray(const std::vector<mrpt::poses::CPose2D>& poses);
std::vector<mrpt::poses::CPose2D> posesFromArray(const py::handle& obj);

void bindErrors(py::module_& m);
void bindObs(py::module_& m);
void bindWorld(py::module_& m);
void bindMaps(py::module_& m);
void bindEval(py::module_& m);
}  // namespace whiskermap::python
