// The stages of a fluid step, one file each, templates on the backend B (CpuBackend,
// CudaBackend): written once, compiled by g++ for the CPU and by nvcc for the GPU.
#pragma once

#include "fluid/build_grid.hpp"
#include "fluid/density_pressure.hpp"
#include "fluid/dfsph_solve.hpp"
#include "fluid/forces.hpp"
#include "fluid/integrate.hpp"
#include "fluid/integrate_density.hpp"
#include "fluid/measure_step.hpp"
#include "fluid/pbf_solve.hpp"
#include "fluid/prepare_boundary.hpp"
#include "fluid/sample_points.hpp"
#include "fluid/wall_forces.hpp"
