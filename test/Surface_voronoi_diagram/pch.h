// Precompiled for every test translation unit: the heavy, stable third-party headers.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <Eigen/Sparse>
#include <catch2/catch.hpp>
