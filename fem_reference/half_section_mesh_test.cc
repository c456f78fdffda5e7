#include "fem_reference/half_section_mesh.h"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace fem
{
  namespace
  {
    constexpr double tol = 1e-13;
  }

  TEST(GradedSegment, NodesSpanTheSegmentWithGeometricSteps)
  {
    const GradedSegment s{0.1, 0.2, 6, 0.8};
    const std::vector<double> x = s.nodes();
    ASSERT_EQ(x.size(), 7u);
    EXPECT_EQ(x.front(), 0.1);
    EXPECT_EQ(x.back(), 0.2);
    const std::vector<double> h = s.steps();
    for (std::size_t i = 1; i < h.size(); ++i)
      EXPECT_NEAR(h[i] / h[i - 1], 0.8, tol);
  }

  TEST(HalfSectionMeshSpec, LevelsAreNested)
  {
    HalfSectionMeshSpec spec;
    spec.split = 0.11;
    for (int level = 0; level < 3; ++level)
      {
        HalfSectionMeshSpec fine = spec;
        spec.level = level;
        fine.level = level + 1;
        const std::vector<double> coarse_r = spec.radial_segment().nodes();
        const std::vector<double> fine_r = fine.radial_segment().nodes();
        ASSERT_EQ(fine_r.size(), 2 * coarse_r.size() - 1);
        for (std::size_t i = 0; i < coarse_r.size(); ++i)
          EXPECT_NEAR(fine_r[2 * i], coarse_r[i], 1e-14);
        const auto coarse_z = spec.axial_segments(), fine_z = fine.axial_segments();
        ASSERT_EQ(coarse_z.size(), 2u);
        for (std::size_t k = 0; k < 2; ++k)
          {
            const std::vector<double> xc = coarse_z[k].nodes(), xf = fine_z[k].nodes();
            for (std::size_t i = 0; i < xc.size(); ++i)
              EXPECT_NEAR(xf[2 * i], xc[i], 1e-14);
          }
      }
  }

  TEST(HalfSectionMeshSpec, GradesTowardTheOuterSideAndTheContactEdge)
  {
    HalfSectionMeshSpec spec;
    spec.split = 0.1;
    const std::vector<double> h_r = spec.radial_segment().steps();
    EXPECT_NEAR(h_r.front() / h_r.back(), spec.radial_ratio, 1e-12);
    const auto z = spec.axial_segments();
    EXPECT_EQ(z[0].end, 0.1);
    EXPECT_EQ(z[1].start, 0.1);
    const std::vector<double> lower = z[0].steps(), upper = z[1].steps();
    EXPECT_LT(lower.back(), lower.front()); // smallest at z = c from below
    EXPECT_LT(upper.front(), upper.back()); // and from above
  }

  // The gmsh file, read back through the gmsh API: quadrilaterals only, a vertex at z = c on
  // the outer side, the node distributions of the spec, all five physical groups.
  TEST(WriteGmshMesh, QuadrilateralsWithTheSpecNodesAndPhysicalGroups)
  {
    HalfSectionMeshSpec spec;
    spec.split = 0.0543 * 2;
    spec.level = 1;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("half_section_test_" + std::to_string(::getpid()) + ".msh"))
                               .string();
    write_gmsh_mesh(spec, path);

    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(path);
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric);
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, 2);
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, 1);
    gmsh::finalize();
    std::filesystem::remove(path);

    const std::vector<double> r_nodes = spec.radial_segment().nodes();
    std::vector<double> z_nodes;
    for (const GradedSegment &s : spec.axial_segments())
      for (const double z : s.nodes())
        if (z_nodes.empty() || z > z_nodes.back())
          z_nodes.push_back(z);
    EXPECT_EQ(tags.size(), r_nodes.size() * z_nodes.size());
    ASSERT_EQ(types.size(), 1u);
    EXPECT_EQ(types[0], 3); // 4-node quadrangle
    EXPECT_EQ(element_tags[0].size(), (r_nodes.size() - 1) * (z_nodes.size() - 1));
    // Every node sits on the tensor grid of the spec (within gmsh's rounding).
    for (std::size_t i = 0; i < tags.size(); ++i)
      {
        const double r = coords[3 * i], z = coords[3 * i + 1];
        const auto near = [](const std::vector<double> &v, double x) {
          return std::any_of(v.begin(), v.end(), [x](double y) { return std::abs(x - y) < 1e-9; });
        };
        EXPECT_TRUE(near(r_nodes, r) && near(z_nodes, z)) << "node (" << r << ", " << z << ")";
      }
    EXPECT_NE(std::find(z_nodes.begin(), z_nodes.end(), *spec.split), z_nodes.end());
    ASSERT_EQ(groups.size(), 5u);
    for (int id = 1; id <= 5; ++id)
      EXPECT_NE(std::find(groups.begin(), groups.end(), std::make_pair(1, id)), groups.end());
  }
} // namespace fem
