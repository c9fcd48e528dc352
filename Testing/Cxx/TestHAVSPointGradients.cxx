/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSPointGradients.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSPointGradients and vtkHAVSIsoSurfaces' shading (issue 46: shaded
// isosurfaces, normals from interpolated point gradients):
// - a linear field on a box of tetrahedra: every point's gradient and every
//   tetrahedron's field, anywhere in it, is the field's gradient (1e-9 and
//   float rounding);
// - a quadratic field: each tetrahedron's field equals its corners' point
//   gradients at its corners and is the same from both tetrahedra at the
//   centroid of every internal face (continuous); control: each
//   tetrahedron's own constant gradient jumps there by more than 1e-3;
//   InterpolateInCells (HAVS's plane sections' vertices) gives each
//   tetrahedron's field at points inside it; control: another one's weights;
// - a flat tetrahedron weighs nothing; a point of it alone gets 0;
// - vtkHAVSMesh::MakeTaggedVertices copies the boundary vertices' gradients
//   with their points (HAVS's shaded isosurfaces);
// - Shade: Phong's terms by hand for a light along the normal, the normal
//   turned towards the eye, a zero gradient left unshaded, the colour clamped;
//   MakeShading takes the lights that are on, their colours times intensity.
#include "havsTestChecks.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSIsoSurfaces.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPointGradients.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace
{
/// The field of tetrahedron t of `fields` at p.
void FieldAt(const std::vector<float>& fields, size_t t, const double p[3], double g[3])
{
  for (int r = 0; r < 3; ++r)
  {
    const float* row = &fields[12 * t + 4 * r];
    g[r] = row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];
  }
}
}

int TestHAVSPointGradients(int, char*[])
{
  auto grid = vtkHAVSDataSets::MakeBox(4, 5, 3, 0.25, 0.0, 1.0);
  vtkNew<vtkHAVSFaceSet> faces;
  faces->Build(grid);
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const vtkIdType n = grid->GetNumberOfPoints();
  std::vector<float> points(3 * n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    double x[3];
    grid->GetPoint(p, x);
    for (int k = 0; k < 3; ++k)
    {
      points[3 * p + k] = static_cast<float>(x[k]);
    }
  }
  const size_t numberOfTets = tets.size() / 4;
  havstest::Check(numberOfTets > 100, "the box has tetrahedra");

  // 1. Linear: s = 2x - 3y + 0.5z.
  {
    std::vector<float> scalars(n);
    for (vtkIdType p = 0; p < n; ++p)
    {
      scalars[p] = 2.0f * points[3 * p] - 3.0f * points[3 * p + 1] + 0.5f * points[3 * p + 2];
    }
    std::vector<double> gradients;
    vtkHAVSPointGradients::Compute(points, scalars, tets, gradients);
    const double exact[3] = { 2.0, -3.0, 0.5 };
    double worstPoint = 0.0, worstField = 0.0;
    for (vtkIdType p = 0; p < n; ++p)
    {
      for (int k = 0; k < 3; ++k)
      {
        worstPoint = std::max(worstPoint, std::fabs(gradients[3 * p + k] - exact[k]));
      }
    }
    std::vector<float> fields;
    vtkHAVSPointGradients::ComputeFields(points, tets, gradients, fields);
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      // A point inside: weights 0.1, 0.2, 0.3, 0.4.
      double p[3] = { 0, 0, 0 };
      for (int v = 0; v < 4; ++v)
      {
        for (int k = 0; k < 3; ++k)
        {
          p[k] += 0.1 * (v + 1) * points[3 * tets[4 * t + v] + k];
        }
      }
      double g[3];
      FieldAt(fields, t, p, g);
      for (int k = 0; k < 3; ++k)
      {
        worstField = std::max(worstField, std::fabs(g[k] - exact[k]));
      }
    }
    std::printf("linear field: points' gradients off by %.2e, tetrahedra's fields by %.2e\n",
      worstPoint, worstField);
    havstest::Check(worstPoint < 1e-5, "linear: every point's gradient is the field's");
    havstest::Check(worstField < 1e-4, "linear: every tetrahedron's field is the gradient");
  }

  // 2. Quadratic: s = x^2 + y^2 + z^2: corners and continuity across faces.
  {
    std::vector<float> scalars(n);
    for (vtkIdType p = 0; p < n; ++p)
    {
      scalars[p] = points[3 * p] * points[3 * p] + points[3 * p + 1] * points[3 * p + 1] +
        points[3 * p + 2] * points[3 * p + 2];
    }
    std::vector<double> gradients;
    vtkHAVSPointGradients::Compute(points, scalars, tets, gradients);
    std::vector<float> fields;
    vtkHAVSPointGradients::ComputeFields(points, tets, gradients, fields);
    double worstCorner = 0.0;
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      for (int v = 0; v < 4; ++v)
      {
        const uint32_t id = tets[4 * t + v];
        const double p[3] = { points[3 * id], points[3 * id + 1], points[3 * id + 2] };
        double g[3];
        FieldAt(fields, t, p, g);
        for (int k = 0; k < 3; ++k)
        {
          worstCorner = std::max(worstCorner, std::fabs(g[k] - gradients[3 * id + k]));
        }
      }
    }
    // Internal faces: the two tetrahedra's fields (and, the control, their
    // own constant gradients) at the face's centroid.
    std::map<std::vector<uint32_t>, size_t> seen;
    double worstJump = 0.0, controlJump = 0.0;
    int shared = 0;
    auto ownGradient = [&](size_t t, double g[3])
    {
      // The tetrahedron's own (constant) gradient: e g = ds, by Cramer's rule.
      double e[3][3], ds[3];
      const uint32_t* ids = &tets[4 * t];
      for (int i = 0; i < 3; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          e[i][k] = points[3 * ids[i + 1] + k] - points[3 * ids[0] + k];
        }
        ds[i] = scalars[ids[i + 1]] - scalars[ids[0]];
      }
      auto det = [](double a[3][3])
      {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
          a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
          a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
      };
      const double d = det(e);
      for (int k = 0; k < 3; ++k)
      {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
        {
          for (int j = 0; j < 3; ++j)
          {
            m[i][j] = j == k ? ds[i] : e[i][j];
          }
        }
        g[k] = det(m) / d;
      }
    };
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      for (int skip = 0; skip < 4; ++skip)
      {
        std::vector<uint32_t> key;
        for (int v = 0; v < 4; ++v)
        {
          if (v != skip)
          {
            key.push_back(tets[4 * t + v]);
          }
        }
        std::sort(key.begin(), key.end());
        auto found = seen.find(key);
        if (found == seen.end())
        {
          seen[key] = t;
          continue;
        }
        const size_t other = found->second;
        double c[3] = { 0, 0, 0 };
        for (uint32_t id : key)
        {
          for (int k = 0; k < 3; ++k)
          {
            c[k] += points[3 * id + k] / 3.0;
          }
        }
        double a[3], b[3], oa[3], ob[3];
        FieldAt(fields, t, c, a);
        FieldAt(fields, other, c, b);
        ownGradient(t, oa);
        ownGradient(other, ob);
        for (int k = 0; k < 3; ++k)
        {
          worstJump = std::max(worstJump, std::fabs(a[k] - b[k]));
          controlJump = std::max(controlJump, std::fabs(oa[k] - ob[k]));
        }
        ++shared;
      }
    }
    std::printf("quadratic field: fields at their corners off by %.2e; %d internal faces: fields "
                "jump by %.2e, control (each tetrahedron's own gradient) by %.2e\n",
      worstCorner, shared, worstJump, controlJump);
    havstest::Check(worstCorner < 1e-5, "quadratic: each field is its corners' gradients there");
    havstest::Check(shared > 100 && worstJump < 1e-5, "quadratic: the fields are continuous");
    havstest::Check(controlJump > 1e-3, "control: the tetrahedra's own gradients jump");

    // The points' gradients interpolated at points inside the tetrahedra (as
    // at a plane section's vertices): the tetrahedra's fields there. Three
    // points a "triangle", one triangle a tetrahedron, and a last one with
    // a cell out of range (0). Control: the next tetrahedron's weights.
    std::vector<float> floatGradients(gradients.begin(), gradients.end());
    std::vector<float> positions;
    std::vector<uint32_t> cells, wrongCells;
    const double mixes[3][4] = { { 0.1, 0.2, 0.3, 0.4 }, { 0.25, 0.25, 0.5, 0.0 },
      { 0.7, 0.1, 0.1, 0.1 } };
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      for (const auto& w : mixes)
      {
        for (int k = 0; k < 3; ++k)
        {
          double x = 0.0;
          for (int v = 0; v < 4; ++v)
          {
            x += w[v] * points[3 * tets[4 * t + v] + k];
          }
          positions.push_back(static_cast<float>(x));
        }
      }
      cells.push_back(static_cast<uint32_t>(t));
      wrongCells.push_back(static_cast<uint32_t>((t + 1) % numberOfTets));
    }
    positions.insert(positions.end(), 9, 0.5f);
    cells.push_back(static_cast<uint32_t>(numberOfTets));
    wrongCells.push_back(0);
    std::vector<float> at, wrong;
    vtkHAVSPointGradients::InterpolateInCells(points, tets, floatGradients, positions, cells, at);
    vtkHAVSPointGradients::InterpolateInCells(
      points, tets, floatGradients, positions, wrongCells, wrong);
    double worstInside = 0.0, controlInside = 0.0;
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      for (int v = 0; v < 3; ++v)
      {
        const size_t i = 9 * t + 3 * v;
        const double p[3] = { positions[i], positions[i + 1], positions[i + 2] };
        double g[3];
        FieldAt(fields, t, p, g);
        for (int k = 0; k < 3; ++k)
        {
          worstInside = std::max(worstInside, std::fabs(at[i + k] - g[k]));
          controlInside = std::max(controlInside, std::fabs(wrong[i + k] - g[k]));
        }
      }
    }
    const bool outOfRange = std::all_of(at.end() - 9, at.end(), [](float g) { return g == 0.0f; });
    std::printf("quadratic field interpolated inside %zu tetrahedra: off their fields by %.2e; "
                "control (the next tetrahedron's weights) %.2e\n",
      numberOfTets, worstInside, controlInside);
    havstest::Check(worstInside < 1e-5 && outOfRange,
      "InterpolateInCells: the tetrahedra's fields inside them; 0 for a cell out of range");
    havstest::Check(controlInside > 1e-3, "control: another tetrahedron's weights differ");
  }

  // 3. A flat tetrahedron weighs nothing.
  {
    const std::vector<float> pts = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, /* flat: */ 0.5f, 0.5f, 0,
      2, 2, 0 };
    const std::vector<float> s = { 0, 1, 2, 3, 7, 9 };
    const std::vector<uint32_t> t = { 0, 1, 2, 3, 1, 2, 4, 5 };
    std::vector<double> g;
    vtkHAVSPointGradients::Compute(pts, s, t, g);
    std::vector<float> fields;
    vtkHAVSPointGradients::ComputeFields(pts, t, g, fields);
    const double at[3] = { 5, 5, 5 };
    double f[3];
    FieldAt(fields, 1, at, f);
    havstest::Check(g[0] == 1.0 && g[1] == 2.0 && g[2] == 3.0 && g[3 * 4] == 0.0 &&
        g[3 * 5 + 1] == 0.0 && std::fabs(f[0] - 0.5) < 1e-6 && std::fabs(f[1] - 1.0) < 1e-6,
      "a flat tetrahedron weighs nothing; its field is its corners' mean, constant");
  }

  // 3b. The boundary vertices' gradients go with their points.
  {
    const std::vector<float> pts = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 };
    const std::vector<float> s = { 0.1f, 0.2f, 0.3f, 0.4f };
    const std::vector<float> g = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 };
    const std::vector<uint32_t> triangles = { 0, 1, 2, 1, 3, 2 };
    const std::vector<uint8_t> boundary = { 0, 1 };
    std::vector<float> taggedPoints, taggedScalars, taggedGradients;
    std::vector<uint32_t> indices;
    const size_t faces = vtkHAVSMesh::MakeTaggedVertices(
      pts, s, 1, triangles, boundary, taggedPoints, taggedScalars, indices, &g, &taggedGradients);
    const std::vector<float> expected = { 4, 5, 6, 10, 11, 12, 7, 8, 9 };
    havstest::Check(faces == 1 && taggedGradients == expected && indices[3] == 4 &&
        taggedPoints[3] == 1.0f && taggedPoints[4] == 1.0f,
      "MakeTaggedVertices: the boundary face's vertices carry their points' gradients");
  }

  // 4. Shade and MakeShading.
  {
    vtkNew<vtkVolumeProperty> property;
    property->ShadeOn();
    property->SetAmbient(0.1);
    property->SetDiffuse(0.6);
    property->SetSpecular(0.5);
    property->SetSpecularPower(4.0);
    vtkNew<vtkLightCollection> lights;
    vtkNew<vtkLight> on, off;
    on->SetPosition(0, 0, 10);
    on->SetFocalPoint(0, 0, 0);
    on->SetIntensity(0.5);
    on->SetDiffuseColor(1.0, 0.5, 1.0);
    on->SetSpecularColor(1.0, 1.0, 0.0);
    off->SwitchOff();
    lights->AddItem(on);
    lights->AddItem(off);
    vtkHAVSIsoSurfaces iso;
    iso.Count = 1;
    iso.MakeShading(property, 0, lights, nullptr);
    havstest::Check(iso.Shaded && iso.LightCount == 1 && iso.Lights[0].Direction[2] == 1.0 &&
        iso.Lights[0].Diffuse[1] == 0.25 && iso.Lights[0].Specular[2] == 0.0,
      "MakeShading: the light that is on, towards it, colours times intensity");
    const double rgba[4] = { 0.2, 0.4, 0.1, 0.5 }; // colour (0.4, 0.8, 0.2)
    const double up[3] = { 0, 0, 3 }, down[3] = { 0, 0, -3 }, eye[3] = { 0, 0, 1 };
    double a[4], b[4], z[4];
    iso.Shade(rgba, up, eye, a);
    iso.Shade(rgba, down, eye, b);
    const double zero[3] = { 0, 0, 0 };
    iso.Shade(rgba, zero, eye, z);
    // n = l = v: ambient + diffuse + specular (r.v = 1).
    const double c[3] = { 0.4, 0.8, 0.2 }, ld[3] = { 0.5, 0.25, 0.5 }, ls[3] = { 0.5, 0.5, 0 };
    bool byHand = true;
    for (int k = 0; k < 3; ++k)
    {
      const double lit = std::min(1.0, 0.1 * c[k] + 0.6 * ld[k] * c[k] + 0.5 * ls[k]) * 0.5;
      byHand = byHand && std::fabs(a[k] - lit) < 1e-12 && a[k] == b[k] && z[k] == rgba[k];
    }
    std::printf("Shade: (%.4f %.4f %.4f %.4f) from (0.2 0.4 0.1 0.5)\n", a[0], a[1], a[2], a[3]);
    havstest::Check(byHand && a[3] == 0.5,
      "Shade: Phong's terms by hand, two-sided, a zero gradient unshaded, opacity kept");
    property->ShadeOff();
    iso.MakeShading(property, 0, lights, nullptr);
    havstest::Check(!iso.Shaded, "MakeShading: ShadeOff leaves the surfaces unshaded");
  }
  return havstest::Result();
}
