// The stages of the interaction with objects (Meteer 2011, §7), templates on the backend B like the
// fluid's: written once, compiled by g++ for the CPU and by nvcc for the GPU.
#pragma once

#include "interaction/boundary_forces.hpp"
#include "interaction/compute_contacts.hpp"
#include "interaction/prepare_object_particles.hpp"
