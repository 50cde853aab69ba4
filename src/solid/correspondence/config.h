/* What a case file says about a correspondence-PD body (paper 003 Sec. 2;
 * ../shared/notes/correspondence_and_penalty.md 1c): everything a bond-based
 * body has (geometry, lattice, density, Young's modulus, kinematics,
 * boundary regions, initial velocities; PdConfig) plus the correspondence
 * model, any Poisson's ratio, J2 plasticity, the damage law and pressure
 * loads. Filled by case/case_solid.c, consumed by cpd_body_create. */
#ifndef NSPD_SOLID_CORRESPONDENCE_CONFIG_H
#define NSPD_SOLID_CORRESPONDENCE_CONFIG_H

#include "solid/pd/config.h"
#include "solid/correspondence/rk_gradient.h"

/* bond_associated: solid/correspondence/bac_force.h (state per bond); classic: Silling's
 * correspondence with the zero-energy penalty, solid/correspondence/classic_force.h (state
 * per point) */
typedef enum { CPD_FORCE_BOND_ASSOCIATED, CPD_FORCE_CLASSIC, CPD_FORCE_COUNT } CpdForce;
typedef enum { CPD_FAMILY_SQUARE, CPD_FAMILY_DISC, CPD_FAMILY_COUNT } CpdFamily;
/* The bond-associated force's frame: lagrangian, bac_force.h's (weights and
 * kernel on the reference bonds); semi_lagrangian, sl_force.h's (paper 003's
 * ref. [10]: on the current ones) */
typedef enum { CPD_FRAME_LAGRANGIAN, CPD_FRAME_SEMI_LAGRANGIAN, CPD_FRAME_COUNT } CpdFrame;
typedef enum {
    CPD_DAMAGE_NONE,
    CPD_DAMAGE_DUCTILE, /* bond equivalent plastic strain from threshold to critical */
    CPD_DAMAGE_BRITTLE, /* bond maximum principal stress past critical_stress */
    CPD_DAMAGE_STRETCH, /* bond stretch past critical_stretch (bond-based PD's, for comparison) */
    CPD_DAMAGE_COUNT
} CpdDamageLaw;

extern const char *const CPD_FORCE_NAMES[CPD_FORCE_COUNT + 1];
extern const char *const CPD_FAMILY_NAMES[CPD_FAMILY_COUNT + 1];
extern const char *const CPD_FRAME_NAMES[CPD_FRAME_COUNT + 1];
extern const char *const CPD_DAMAGE_NAMES[CPD_DAMAGE_COUNT + 1];

/* A pressure p(t) filling `region` (a cavity, or the space outside the
 * body) pushes on the faces of the body's lattice cells that border it
 * (body.c); p(t) is a trapezoid: 0 to `peak` over `rise`, held for
 * `hold`, back to 0 over `fall` (s; fall <= 0: held for ever), or where
 * expr is not 0 the load expression pd.expressions[expr - 1] of (t, x, y,
 * z), x a loaded point's reference position. */
typedef struct {
    char name[PD_MAX_NAME];
    ShapeSet region;
    double peak; /* Pa */
    double rise, hold, fall;
    uint16_t expr;
} CpdPressure;

typedef struct {
    PdConfig pd;          /* model: plane_strain or plane_stress; horizon_factor = delta / dx */
    double poisson_ratio; /* any in (-1, 0.5) */
    double yield_stress;  /* sigma_Y, Pa; 0: elastic */
    double hardening;     /* H = d sigma_y / d eqps, Pa */
    CpdForce force;
    CpdFrame frame;       /* bond_associated: lagrangian (the default) or semi_lagrangian */
    double stabilisation; /* classic: C_s of the zero-energy penalty (Silling 2017) */
    CpdFamily family;
    RkKernel kernel; /* the influence function omega (both forces) */
    int rk_order;    /* bond_associated: RK gradient weights of order 1, 2 (the paper's;
                        0 means 2) or 3 (cubic where the family fits one) */
    CpdDamageLaw damage;
    double plastic_strain_threshold, plastic_strain_critical; /* ductile: eps_th, eps_cr */
    double critical_stress;                                   /* brittle: sigma_cr, Pa */
    double damage_ramp;      /* brittle: relative width of the ramp below sigma_cr (0: a step) */
    double critical_stretch; /* stretch: s_c */
    int pressure_count;
    CpdPressure *pressures;
} CpdConfig;

/* p(t) of a pressure load, Pa. */
double cpd_pressure_at(const CpdPressure *p, double t);
void cpd_config_free(CpdConfig *cfg);

#endif
