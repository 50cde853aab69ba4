/* Material relations of bond-based peridynamics (paper 000 Eqs. 15, 18).
 *
 * Bond-based PD fixes Poisson's ratio: 1/3 in plane stress, 1/4 in plane
 * strain and 3D. The micromodulus is calibrated so that, for a point deep
 * inside the body, the PD strain energy of a homogeneous deformation equals
 * the classical one:
 *     plane stress  c = 9 E / (pi h delta^3)
 *     plane strain  c = 48 E / (5 pi h delta^3)
 *     3D            c = 12 E / (pi delta^4)
 * The critical stretch follows from equating the energy to break all bonds
 * across a unit crack area with G_c (Eq. 18, k the bulk modulus of the
 * model: 2D plane stress k = E/(2(1-nu)), plane strain k = E/(2(1+nu)(1-2nu)),
 * 3D K = E/(3(1-2nu))):
 *     2D  s_c = sqrt(pi G_c / (3 k delta)),   3D  s_c = sqrt(5 G_c / (9 K delta)). */
#include "solid/pd/config.h"

#include "core/mem.h"

#include <math.h>

const char *const PD_MODEL_NAMES[PD_MODEL_COUNT + 1] = {"plane_stress", "plane_strain", "3d", NULL};
const char *const PD_INTEGRATOR_NAMES[PD_INTEGRATOR_COUNT + 1] = {"euler_cromer", "velocity_verlet",
                                                                  NULL};
const char *const PD_VOLUME_NAMES[PD_VOLUME_COUNT + 1] = {"none", "linear", NULL};
const char *const PD_SURFACE_NAMES[PD_SURFACE_COUNT + 1] = {"none", "energy", NULL};
const char *const PD_LATTICE_NAMES[PD_LATTICE_COUNT + 1] = {"square", "polar", "abaqus", NULL};

double pd_model_poisson_ratio(PdModel model) {
    return model == PD_PLANE_STRESS ? 1.0 / 3.0 : 0.25;
}

double pd_micromodulus(const PdConfig *cfg) {
    double delta = cfg->horizon_factor * cfg->spacing, E = cfg->youngs_modulus;
    switch (cfg->model) {
    case PD_PLANE_STRESS:
        return 9.0 * E / (M_PI * cfg->thickness * pow(delta, 3));
    case PD_PLANE_STRAIN:
        return 48.0 * E / (5.0 * M_PI * cfg->thickness * pow(delta, 3));
    default:
        return 12.0 * E / (M_PI * pow(delta, 4));
    }
}

static double bulk_modulus(const PdConfig *cfg) {
    double E = cfg->youngs_modulus, nu = pd_model_poisson_ratio(cfg->model);
    switch (cfg->model) {
    case PD_PLANE_STRESS:
        return E / (2.0 * (1.0 - nu));
    case PD_PLANE_STRAIN:
        return E / (2.0 * (1.0 + nu) * (1.0 - 2.0 * nu));
    default:
        return E / (3.0 * (1.0 - 2.0 * nu));
    }
}

double pd_critical_stretch_from_energy(const PdConfig *cfg, double fracture_energy) {
    double delta = cfg->horizon_factor * cfg->spacing, k = bulk_modulus(cfg);
    if (cfg->dim == 2) return sqrt(M_PI * fracture_energy / (3.0 * k * delta));
    return sqrt(5.0 * fracture_energy / (9.0 * k * delta));
}

double pd_classical_uniaxial_energy(const PdConfig *cfg, double strain) {
    double E = cfg->youngs_modulus, nu = pd_model_poisson_ratio(cfg->model);
    /* W = (1/2) M eps^2 with M the constrained (P-wave) modulus of the model */
    double M = cfg->model == PD_PLANE_STRESS ? E / (1.0 - nu * nu)
                                             : E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    return 0.5 * M * strain * strain;
}

double pd_bar_wave_speed(const PdConfig *cfg) {
    return sqrt(cfg->youngs_modulus / cfg->density);
}

double pd_shear_wave_speed(const PdConfig *cfg) {
    double nu = pd_model_poisson_ratio(cfg->model);
    return sqrt(cfg->youngs_modulus / (2.0 * (1.0 + nu)) / cfg->density);
}

/* Rayleigh speed: the root xi = (c_R/c_S)^2 in (0, 1) of
 *     (2 - xi)^2 = 4 sqrt(1 - xi) sqrt(1 - xi k),  k = (c_S/c_P)^2,
 * with c_P the in-plane longitudinal speed of the model (plane stress uses
 * the plane-stress P modulus E/(1-nu^2)). Besides the trivial root xi = 0,
 * the function is negative just above 0 and positive at 1, with one sign
 * change in between: bisection. */
double pd_rayleigh_wave_speed(const PdConfig *cfg) {
    double E = cfg->youngs_modulus, nu = pd_model_poisson_ratio(cfg->model);
    double G = E / (2.0 * (1.0 + nu));
    double M = cfg->model == PD_PLANE_STRESS ? E / (1.0 - nu * nu)
                                             : E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    double k = G / M, lo = 1e-9, hi = 1.0 - 1e-12;
    for (int it = 0; it < 200; it++) {
        double xi = 0.5 * (lo + hi);
        double f = (2.0 - xi) * (2.0 - xi) - 4.0 * sqrt(1.0 - xi) * sqrt(1.0 - xi * k);
        if (f < 0)
            lo = xi;
        else
            hi = xi;
    }
    return sqrt(0.5 * (lo + hi)) * pd_shear_wave_speed(cfg);
}

void pd_config_free(PdConfig *cfg) {
    shapeset_free(&cfg->failure_region);
    shapeset_free(&cfg->geometry);
    for (int i = 0; i < cfg->boundary_count; i++) shapeset_free(&cfg->boundaries[i].region);
    for (int i = 0; i < cfg->initial_velocity_count; i++)
        shapeset_free(&cfg->initial_velocities[i].region);
    nspd_free(&cfg->precracks);
    nspd_free(&cfg->boundaries);
    nspd_free(&cfg->initial_velocities);
    nspd_free(&cfg->expressions);
    for (int i = 0; i < cfg->material_count; i++) shapeset_free(&cfg->materials[i].region);
    nspd_free(&cfg->materials);
    cfg->material_count = 0;
    mesh_points_free(&cfg->mesh);
}
