/* What a case file says about a peridynamic body: geometry, material,
 * discretisation, pre-cracks, boundary regions and numerics. Filled by
 * io/case_solid.c, consumed by bond_body_create(). Units are SI. */
#ifndef NSPD_SOLID_PD_CONFIG_H
#define NSPD_SOLID_PD_CONFIG_H

#include "core/expr.h"
#include "core/shape.h"
#include "solid/pd/contact.h"
#include "solid/pd/lattice.h"
#include "solid/pd/mesh_points.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum { PD_PLANE_STRESS, PD_PLANE_STRAIN, PD_3D, PD_MODEL_COUNT } PdModel;
typedef enum { PD_EULER_CROMER, PD_VELOCITY_VERLET, PD_INTEGRATOR_COUNT } PdIntegrator;
typedef enum { PD_VOLUME_NONE, PD_VOLUME_LINEAR, PD_VOLUME_COUNT } PdVolumeCorrection;
typedef enum { PD_SURFACE_NONE, PD_SURFACE_ENERGY, PD_SURFACE_COUNT } PdSurfaceCorrection;
typedef enum {
    PD_LATTICE_SQUARE,
    PD_LATTICE_POLAR,
    PD_LATTICE_ABAQUS,
    PD_LATTICE_COUNT
} PdLatticeKind;

extern const char *const PD_MODEL_NAMES[PD_MODEL_COUNT + 1];
extern const char *const PD_INTEGRATOR_NAMES[PD_INTEGRATOR_COUNT + 1];
extern const char *const PD_VOLUME_NAMES[PD_VOLUME_COUNT + 1];
extern const char *const PD_SURFACE_NAMES[PD_SURFACE_COUNT + 1];
extern const char *const PD_LATTICE_NAMES[PD_LATTICE_COUNT + 1];

enum { PD_MAX_NAME = 64, PD_MAX_EXPRESSIONS = 256 };

/* A region of points whose motion is prescribed or loaded. Components not
 * in a mask are free. Each value is a constant, or where its *_expr entry
 * k is not 0 the load expression PdConfig.expressions[k - 1] of (t, x, y,
 * z), x the point's reference position (core/expr.h). */
typedef struct {
    char name[PD_MAX_NAME];
    ShapeSet region;
    unsigned velocity_mask;     /* bit d: velocity component d prescribed */
    double velocity[3];         /* m/s */
    unsigned displacement_mask; /* bit d: displacement component d held at the value */
    double displacement[3];     /* m */
    double force_density[3];    /* N/m^3 added on the region's points */
    uint16_t velocity_expr[3], displacement_expr[3], force_expr[3];
} PdBoundaryRegion;

/* Bonds crossing it start broken. 2D: the segment a-b. 3D: the
 * parallelogram a + s e1 + t e2, s, t in [0, 1]. */
typedef struct {
    double a[3], b[3];   /* 2D segment ends */
    double e1[3], e2[3]; /* 3D edges from a */
} PdPrecrack;

typedef struct {
    ShapeSet region;
    double velocity[3];
    uint16_t velocity_expr[3]; /* as in PdBoundaryRegion, at t = 0 */
} PdInitialVelocity;

/* One of several materials of a body (solid.material as a list): the
 * points in `region` (the first material whose region holds a point; the
 * last may have none: the rest) take its density and Young's modulus. The
 * first is also PdConfig's density and youngs_modulus; the critical
 * stretch is the body's, one for all. */
typedef struct {
    char name[PD_MAX_NAME];
    ShapeSet region;
    double density, youngs_modulus;
} PdMaterial;

typedef struct {
    PdModel model;
    int dim;               /* 2 or 3, from the model */
    double thickness;      /* m, 2D only */
    double spacing;        /* lattice spacing dx, m */
    double horizon_factor; /* m: horizon delta = m dx */
    double lattice_origin[3];
    bool has_lattice_origin; /* else the lattice starts half a spacing inside the bounding box */
    /* square: the lattice of spacing dx in `geometry`; polar (the
     * correspondence solid only): `polar`'s elements whose centroids
     * `geometry` holds (all if it has no shape), each of its own volume;
     * spacing is then its radial spacing (r_o - r_i) / rings; abaqus (the
     * correspondence solid only): `mesh`'s points whose centroids
     * `geometry` holds (all if it has no shape), each of its own volume */
    PdLatticeKind lattice_kind;
    PolarLattice polar;
    MeshPoints mesh; /* owned */

    double density;          /* kg/m^3 */
    double youngs_modulus;   /* Pa */
    double critical_stretch; /* s_c; computed from fracture_energy when that is given */
    double fracture_energy;  /* G_c, J/m^2; 0 when s_c is given directly */
    bool failure;            /* bonds may break */
    ShapeSet failure_region; /* empty: everywhere; else bonds whose midpoint lies inside */

    ShapeSet geometry;
    int precrack_count;
    PdPrecrack *precracks;
    int boundary_count;
    PdBoundaryRegion *boundaries;
    int initial_velocity_count;
    PdInitialVelocity *initial_velocities;
    double body_force[3]; /* N/m^3 on every point */
    uint16_t body_force_expr[3];
    int expression_count; /* the load expressions the *_expr entries name */
    Expr *expressions;

    PdVolumeCorrection volume_correction;
    PdSurfaceCorrection surface_correction;
    PdIntegrator integrator;
    PdContactConfig contact; /* short-range contact (contact.h), bond-based */
    /* Several materials (bond-based; 0 or 1: the one of density and
     * youngs_modulus): bonds join points of two materials only where
     * materials_bonded, with the micromodulus of the two in series. */
    int material_count;
    PdMaterial *materials;
    bool materials_bonded;
} PdConfig;

/* Poisson's ratio that bond-based PD implies for the model (1/3 or 1/4). */
double pd_model_poisson_ratio(PdModel model);
/* Micromodulus c of Eq. 15 (N/m^6 in 3D; 2D includes 1/thickness). */
double pd_micromodulus(const PdConfig *cfg);
/* Critical stretch from G_c (paper 000 Eq. 18, with the model's bulk modulus). */
double pd_critical_stretch_from_energy(const PdConfig *cfg, double fracture_energy);
/* Classical strain energy density of a uniaxial strain `strain` (the
 * reference for the surface correction), J/m^3. */
double pd_classical_uniaxial_energy(const PdConfig *cfg, double strain);
/* Wave speeds of the continuum the model represents, m/s. */
double pd_bar_wave_speed(const PdConfig *cfg);      /* sqrt(E/rho) */
double pd_shear_wave_speed(const PdConfig *cfg);    /* sqrt(G/rho) */
double pd_rayleigh_wave_speed(const PdConfig *cfg); /* root of the Rayleigh equation */

void pd_config_free(PdConfig *cfg);

/* The partial volume nu_ij of a neighbour at distance xi_len (setup,
 * corrections and diagnostics share it). */
static inline double pd_volume_factor(double xi_len, double horizon, double spacing,
                                      PdVolumeCorrection mode) {
    /* Linear partial-volume correction: a neighbour whose cell is cut by the
     * horizon sphere contributes the fraction of its cell inside it. */
    if (mode == PD_VOLUME_NONE || xi_len <= horizon - 0.5 * spacing) return 1.0;
    double f = (horizon + 0.5 * spacing - xi_len) / spacing;
    return f > 0.0 ? f : 0.0;
}

#endif
