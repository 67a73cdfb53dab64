// A render divided among MPI ranks (app/mpi_session.h): rank r renders the tiles t with
// t % size == r for every sample pass (renderer/tracing/integrator.h's RenderDivision); a noise
// check sums the films onto rank 0, which estimates the noise and broadcasts it, so every rank
// stops at the same sample count; at the end the films and counters are summed onto rank 0. Each
// film slot is filled by one rank only (x + 0 = x), so rank 0's film is the one-process film bit
// for bit. Without distribution: no division.
#pragma once
#include "renderer/tracing/integrator.h"

namespace hylios {

RenderDivision renderDivisionAcrossRanks();

}  // namespace hylios
