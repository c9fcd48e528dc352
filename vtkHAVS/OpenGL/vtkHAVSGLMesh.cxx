/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLMesh.h"

#include "vtkHAVSGLCapabilities.h"

#include "vtkHAVSMesh.h"
#include "vtkHAVSPointGradients.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLMesh);

namespace
{
/// Fills the buffers that the face vertex shader reads, points (location 0,
/// 3 floats each) and normalized scalars (location 1, `components` floats
/// each), and points `array`'s attributes at them.
void UploadVertexAttributes(vtkHAVSGLVertexArray& array, vtkHAVSGLBuffer& pointBuffer,
  vtkHAVSGLBuffer& scalarBuffer, const std::vector<float>& points,
  const std::vector<float>& scalars, GLenum usage, int components)
{
  pointBuffer.Update(GL_ARRAY_BUFFER, points, 0, usage);
  scalarBuffer.Update(GL_ARRAY_BUFFER, scalars, 0, usage);
  array.SetAttribute(0, pointBuffer, 3);
  array.SetAttribute(1, scalarBuffer, components);
}
}

vtkHAVSGLMesh::vtkHAVSGLMesh() = default;

vtkHAVSGLMesh::~vtkHAVSGLMesh()
{
  if (this->VertexArray.IsCreated() || this->SectionArray.IsCreated())
  {
    vtkErrorMacro("ReleaseGraphicsResources was not called before destruction.");
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::UploadGeometry(
  const std::vector<float>& points, const std::vector<float>& scalars, int components)
{
  this->Points = points;
  this->Scalars = scalars;
  this->Components = components;
  this->VertexCapacity = points.size() / 3;
  this->Gradients.clear(); // (a new mesh: its gradients come again)
  this->GradientsVersion = 0;
  UploadVertexAttributes(this->VertexArray, this->PointBuffer, this->ScalarBuffer, points, scalars,
    GL_STATIC_DRAW, components);
  if (!this->IndexBuffer.GetHandle())
  {
    this->IndexBuffer.Update(GL_ELEMENT_ARRAY_BUFFER, nullptr, 0, 0, GL_STREAM_DRAW);
  }
  this->VertexArray.SetIndices(&this->IndexBuffer);
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::UploadScalars(const std::vector<float>& scalars)
{
  if (!this->VertexArray.IsCreated() || scalars.size() != this->Scalars.size())
  {
    vtkErrorMacro("UploadScalars: " << scalars.size() << " scalars for " << this->Scalars.size()
                                    << " uploaded.");
    return;
  }
  this->Scalars = scalars;
  this->ScalarBuffer.Write(0, scalars.data(), scalars.size() * sizeof(float));
}

//------------------------------------------------------------------------------
bool vtkHAVSGLMesh::UploadFaceOrder(
  const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& boundary, bool tagged)
{
  if (!this->VertexArray.IsCreated())
  {
    vtkErrorMacro("UploadFaceOrder before UploadGeometry.");
    return false;
  }
  const size_t numPoints = this->Points.size() / 3;
  const int nc = this->Components;
  const std::vector<uint32_t>* indices = &triangles;
  std::vector<uint32_t> rewritten;
  std::vector<float> points, scalars, gradients;
  // (Shaded isosurfaces: the boundary vertices' gradients copied with them.)
  const bool shaded = this->HasGradients();
  const size_t boundaryFaces = tagged
    ? vtkHAVSMesh::MakeTaggedVertices(this->Points, this->Scalars, nc, triangles, boundary, points,
        scalars, rewritten, shaded ? &this->Gradients : nullptr, &gradients)
    : 0;
  if (boundaryFaces > 0)
  {
    // The boundary faces' own vertices, in draw order, after the points.
    const size_t vertices = numPoints + 3 * boundaryFaces;
    if (vertices > this->VertexCapacity)
    {
      // Grow once: the points again, room for the boundary vertices.
      std::vector<float> allPoints(this->Points), allScalars(this->Scalars);
      allPoints.resize(3 * vertices);
      allScalars.resize(nc * vertices);
      UploadVertexAttributes(this->VertexArray, this->PointBuffer, this->ScalarBuffer, allPoints,
        allScalars, GL_DYNAMIC_DRAW, nc);
      this->VertexCapacity = vertices;
      if (shaded)
      {
        std::vector<float> allGradients(this->Gradients);
        allGradients.resize(3 * vertices);
        this->GradientBuffer.Update(GL_ARRAY_BUFFER, allGradients, 0, GL_DYNAMIC_DRAW);
        this->VertexArray.SetAttribute(2, this->GradientBuffer, 3);
      }
    }
    if (shaded)
    {
      this->GradientBuffer.Write(
        3 * numPoints * sizeof(float), gradients.data(), gradients.size() * sizeof(float));
    }
    this->PointBuffer.Write(
      3 * numPoints * sizeof(float), points.data(), points.size() * sizeof(float));
    this->ScalarBuffer.Write(
      nc * numPoints * sizeof(float), scalars.data(), scalars.size() * sizeof(float));
    indices = &rewritten;
  }
  // (The same buffer object, newly filled: the vertex array keeps pointing at it.)
  this->IndexBuffer.Update(GL_ELEMENT_ARRAY_BUFFER, *indices, 0, GL_STREAM_DRAW);
  this->IndexCount = static_cast<GLsizei>(indices->size());
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::UploadSections(
  const std::vector<vtkHAVSFramePlanes::Section>& sections, const std::vector<uint32_t>& tets)
{
  this->SectionDraws.clear();
  std::vector<float> points, scalars;
  std::vector<uint32_t> cells;
  for (const vtkHAVSFramePlanes::Section& section : sections)
  {
    const GLsizei count = static_cast<GLsizei>(section.Scalars.size());
    if (count < 3 || section.Points.size() != 3 * section.Scalars.size())
    {
      continue;
    }
    this->SectionDraws.push_back(
      { section.PlaneIndex, section.Entering, static_cast<GLint>(points.size() / 3), count });
    points.insert(points.end(), section.Points.begin(), section.Points.end());
    for (float s : section.Scalars)
    {
      scalars.insert(scalars.end(), static_cast<size_t>(this->Components), s);
    }
    cells.insert(cells.end(), section.Cells.begin(), section.Cells.end());
    cells.resize(points.size() / 9, 0); // (a section without its cells: out of range below)
  }
  if (this->SectionDraws.empty())
  {
    return;
  }
  UploadVertexAttributes(this->SectionArray, this->SectionPoints, this->SectionScalars, points,
    scalars, GL_STREAM_DRAW, this->Components);
  if (this->HasGradients())
  {
    // Shaded isosurfaces: the sections' vertices carry the interpolated
    // gradients at attribute 2, as the faces' vertices do (a crossing between
    // a section's fragment and a face's mixes the two).
    std::vector<float> gradients;
    vtkHAVSPointGradients::InterpolateInCells(
      this->Points, tets, this->Gradients, points, cells, gradients);
    this->SectionGradients.Update(GL_ARRAY_BUFFER, gradients, 0, GL_STREAM_DRAW);
    this->SectionArray.SetAttribute(2, this->SectionGradients, 3);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::ReadBack(
  std::vector<float>& points, std::vector<float>& scalars, std::vector<uint32_t>& indices) const
{
  auto read = [](const vtkHAVSGLBuffer& buffer, auto& out, size_t count)
  {
    out.resize(count);
    if (count > 0)
    {
      buffer.Read(0, out.data(), count * sizeof(out[0]));
    }
  };
  const size_t vertices = std::max(this->VertexCapacity, this->Points.size() / 3);
  read(this->PointBuffer, points, 3 * vertices);
  read(this->ScalarBuffer, scalars, this->Components * vertices);
  read(this->IndexBuffer, indices, static_cast<size_t>(this->IndexCount));
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::DrawFaces(vtkShaderProgram* program, bool flipFacing, int batches,
  const std::function<void(int)>& betweenBatches)
{
  const bool roles = program->IsUniformUsed("havsRole");
  const bool ownPlane = program->IsUniformUsed("havsOwnPlane");
  // Isosurface frames place a fragment on its face: its scalar and distance
  // where the pixel centre's ray meets the face, in double, or clamped to the
  // face's where that ray passes outside it (vtkHAVSKBufferLib.glsl,
  // havsOnFace): the face's indices and the vertices' scalars and points read
  // by gl_PrimitiveID + havsFaceBase, which every draw sets (-1: as the
  // rasterizer gives it, a section, or scalars that are not one float a vertex).
  const bool faceBase = program->IsUniformUsed("havsFaceBase");
  const bool clamp = faceBase && this->Components == 1;
  if (clamp)
  {
    this->IndexBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, 14);
    this->ScalarBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, 15);
    this->PointBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, 16);
  }
  auto drawSections = [&](bool entering)
  {
    for (const SectionDraw& d : this->SectionDraws)
    {
      if (d.Entering != entering)
      {
        continue;
      }
      if (faceBase)
      {
        program->SetUniformi("havsFaceBase", -1);
      }
      if (roles)
      {
        program->SetUniformi("havsRole", entering ? 1 : 2);
      }
      if (ownPlane)
      {
        program->SetUniformi("havsOwnPlane", d.PlaneIndex);
      }
      this->SectionArray.Bind();
      glDrawArrays(GL_TRIANGLES, d.First, d.Count);
    }
    if (roles)
    {
      program->SetUniformi("havsRole", 0);
    }
    if (ownPlane)
    {
      program->SetUniformi("havsOwnPlane", -1);
    }
  };
  drawSections(true);
  const GLsizei faces = this->IndexCount / 3;
  batches = betweenBatches ? std::max(1, std::min(batches, static_cast<int>(faces))) : 1;
  const long long perFinish = vtkHAVSGLCapabilities::FacesPerFinish();
  for (int b = 0; b < batches; ++b)
  {
    const GLsizei first = static_cast<GLsizei>(static_cast<long long>(faces) * b / batches);
    const GLsizei last = static_cast<GLsizei>(static_cast<long long>(faces) * (b + 1) / batches);
    glFrontFace(flipFacing ? GL_CW : GL_CCW);
    this->VertexArray.Bind();
    // In pieces, at most two queued (a software rasterizer's queued scenes).
    vtkHAVSGLCapabilities::DrawInPieces(first, last, perFinish,
      [&](long long begin, long long end)
      {
        if (faceBase)
        {
          program->SetUniformi("havsFaceBase", clamp ? static_cast<int>(begin) : -1);
        }
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * (end - begin)), GL_UNSIGNED_INT,
          reinterpret_cast<const void*>(3 * sizeof(GLuint) * static_cast<size_t>(begin)));
      });
    glFrontFace(GL_CCW);
    if (b + 1 < batches)
    {
      betweenBatches(b);
    }
  }
  drawSections(false);
  vtkHAVSGLVertexArray::Unbind();
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkHAVSGLBuffer* b :
    { &this->PointBuffer, &this->ScalarBuffer, &this->IndexBuffer, &this->SectionPoints,
      &this->SectionScalars, &this->GradientBuffer, &this->SectionGradients })
  {
    b->Release();
  }
  this->SectionDraws.clear();
  this->VertexArray.Release();
  this->SectionArray.Release();
  this->IndexCount = 0;
  this->VertexCapacity = 0;
  this->GeometryVersion = this->ScalarVersion = this->OrderVersion = this->SectionsVersion = 0;
  this->SectionsGradientsVersion = 0;
  this->OrderTagged = false;
  this->Gradients.clear();
  this->GradientsVersion = 0;
}

//------------------------------------------------------------------------------
int vtkHAVSGLMesh::UpdateGeometry(vtkHAVSMesh* mesh)
{
  if (this->GeometryVersion != mesh->GetBuildTime())
  {
    this->UploadGeometry(
      mesh->GetVertexPoints(), mesh->GetVertexScalars(), mesh->GetVertexScalarComponents());
    this->GeometryVersion = mesh->GetBuildTime();
    this->ScalarVersion = mesh->GetScalarTime();
    this->OrderVersion = 0;
    return UploadedGeometry;
  }
  if (this->ScalarVersion != mesh->GetScalarTime())
  {
    // A new time step on the same mesh: the scalars only (the boundary
    // vertices' copies with the next face-order upload).
    this->UploadScalars(mesh->GetVertexScalars());
    this->ScalarVersion = mesh->GetScalarTime();
    this->OrderVersion = 0;
    return UploadedScalars;
  }
  return UploadedNothing;
}

bool vtkHAVSGLMesh::UpdateGradients(const std::vector<float>* gradients, vtkMTimeType version)
{
  if (!gradients)
  {
    this->Gradients.clear();
    this->GradientsVersion = 0;
    return false;
  }
  if (this->GradientsVersion == version || !this->VertexArray.IsCreated() ||
    gradients->size() != this->Points.size())
  {
    return false;
  }
  this->Gradients = *gradients;
  std::vector<float> all(*gradients);
  all.resize(3 * std::max(this->VertexCapacity, this->Points.size() / 3));
  this->GradientBuffer.Update(GL_ARRAY_BUFFER, all, 0, GL_DYNAMIC_DRAW);
  this->VertexArray.SetAttribute(2, this->GradientBuffer, 3);
  this->GradientsVersion = version;
  this->OrderVersion = 0; // (the boundary vertices' copies with the next order)
  return true;
}

bool vtkHAVSGLMesh::UpdateFaceOrder(const std::vector<uint32_t>& triangles,
  const std::vector<uint8_t>& boundary, bool tagged, vtkMTimeType version, bool* failed)
{
  *failed = false;
  if (this->OrderVersion == version && this->OrderTagged == tagged)
  {
    return false;
  }
  if (!this->UploadFaceOrder(triangles, boundary, tagged))
  {
    *failed = true;
    return false;
  }
  this->OrderVersion = version;
  this->OrderTagged = tagged;
  return true;
}

bool vtkHAVSGLMesh::UpdateSections(const std::vector<vtkHAVSFramePlanes::Section>& sections,
  vtkMTimeType version, const std::vector<uint32_t>& tets)
{
  if (this->SectionsVersion == version && this->SectionsGradientsVersion == this->GradientsVersion)
  {
    return false;
  }
  this->UploadSections(sections, tets);
  this->SectionsVersion = version;
  this->SectionsGradientsVersion = this->GradientsVersion;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Faces uploaded: " << this->IndexCount / 3 << ", sections "
     << this->SectionDraws.size() << "\n";
}

VTK_ABI_NAMESPACE_END
