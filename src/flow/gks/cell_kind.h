/* Cell kinds of the flow grid (uint8 per cell; solver.h says what each
 * kind means for the step). A header of its own so that the kernels
 * (recon_kernel.h, update_kernel.h) can test kinds without pulling in the
 * solver's interface. */
#ifndef NSPD_FLOW_GKS_CELL_KIND_H
#define NSPD_FLOW_GKS_CELL_KIND_H

enum { FLOW_CELL_FLUID = 0, FLOW_CELL_SOLID = 1, FLOW_CELL_GHOST = 2 };

#endif
