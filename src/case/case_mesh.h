/* Solids from a mesh file (issue 61): solid.lattice {kind: abaqus, file,
 * scale, translate} reads an Abaqus .inp (io/inp_read.h) into the solid's
 * points, one per element at its centroid with its area, and keeps the
 * mesh while the solid is read so that boundaries and initial velocities
 * can name its sets (`set: NAME`). */
#ifndef NSPD_CASE_CASE_MESH_H
#define NSPD_CASE_CASE_MESH_H

#include "core/shape.h"
#include "io/cfg_tree.h"
#include "io/inp_read.h"
#include "solid/pd/mesh_points.h"

#include <stdbool.h>

typedef struct {
    bool loaded;
    InpMesh inp;
    double scale, shift[3]; /* the file's coordinates -> m: scale x + shift */
    char path[4096];
} CaseMesh;

/* The lattice map's file (relative to the case file), scale and translate:
 * the mesh read into *mesh and its elements' centroids and measures (in m)
 * into *points; *mean_size the mean element size, (sum of areas / count)^(1/2)
 * in 2D. A file that is not a mesh nspd takes is refused at lattice.file with
 * its line (or byte); 3D elements in a `dim` 2 solid too. */
int case_read_abaqus(CfgNode *lattice, int dim, CaseMesh *mesh, MeshPoints *points,
                     double *mean_size);

/* item[key], a set's name or a list of names, as a region: the elements of
 * the mesh's element sets, or of a node set the elements whose nodes it
 * holds all (an element set wins over a node set of the same name), each
 * element its polygon. Absent: *given false, region untouched. Refused
 * when the solid has no mesh (mesh NULL or not loaded), for a name the
 * file does not define, or a set that selects no element. */
int case_read_set_region(CfgNode *item, const char *key, const CaseMesh *mesh, ShapeSet *region,
                         bool *given);

void case_mesh_free(CaseMesh *mesh);

#endif
