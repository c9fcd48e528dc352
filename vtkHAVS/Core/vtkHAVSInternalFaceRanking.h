/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSInternalFaceRanking.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSInternalFaceRanking
 * @brief   The internal faces of a mesh ranked from most to least important,
 *          for the dynamic level of detail.
 *
 * Plain C++, no OpenGL. A level-of-detail frame draws every boundary face and
 * the first |I| internal faces of this ranking, in the frame's face order
 * (Callahan et al., "Interactive rendering of large unstructured grids using
 * dynamic level-of-detail", Vis 2005; thesis chapter 5). The strategies:
 * - Topology: layers peeled from the boundary (the thesis' EXTRACT_LAYERS:
 *   the faces on the boundary of what is left get the current layer, every
 *   cell sharing a vertex with them is peeled); whole layers ranked in an even
 *   spread through the mesh (the radical-inverse order of the layer index),
 *   the faces no layer reached last, in random order;
 * - ViewAligned: the faces clustered once per input by their normal (a 4 x 4
 *   grid on each face of the cube around the unit sphere: 96 clusters); per
 *   view the clusters ranked by how squarely they face the view direction,
 *   random order within a cluster (UpdateView());
 * - Field: stratified on the histogram of the faces' mean normalized scalar
 *   (128 bins): the same number of faces from every bin, in random order;
 * - Area: by area times a uniform random number;
 * - Random: a uniformly random order (the control the thesis compares with).
 * Every random choice comes from a fixed seed: the same input gives the same
 * ranking. The preprocessing runs where it can in parallel (vtkSMPTools),
 * reports progress through a callback and says its time and memory.
 */
#ifndef vtkHAVSInternalFaceRanking_h
#define vtkHAVSInternalFaceRanking_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"

#include <array>      // For std::array
#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSMesh;

class VTKHAVSCORE_EXPORT vtkHAVSInternalFaceRanking : public vtkObject
{
public:
  static vtkHAVSInternalFaceRanking* New();
  vtkTypeMacro(vtkHAVSInternalFaceRanking, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Strategies
  {
    Topology = 0,
    ViewAligned = 1,
    Field = 2,
    Area = 3,
    Random = 4
  };
  /// "Topology", "ViewAligned", "Field", "Area", "Random"; "Unknown" else.
  static const char* GetStrategyName(int strategy);

  ///@{
  /// The strategy (Strategies; Area by default) and the random seed.
  vtkSetClampMacro(Strategy, int, Topology, Random);
  vtkGetMacro(Strategy, int);
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  /// Called with the fraction done (0 to 1) during a preprocessing.
  using ProgressCallback = std::function<void(double)>;

  /**
   * Ranks the mesh's internal faces when the mesh, its scalars (Field), the
   * strategy or the seed changed since the last call. Returns true when the
   * ranking changed.
   */
  bool Update(vtkHAVSMesh* mesh, const ProgressCallback& progress = nullptr);

  /**
   * ViewAligned: ranks the clusters for the view direction `direction` (in
   * the mesh's coordinates); does nothing for the other strategies. Returns
   * true when the ranking changed.
   */
  bool UpdateView(const double direction[3]);

  /// No rank: a boundary face (always drawn).
  static constexpr uint32_t NoRank = 0xFFFFFFFFu;
  /**
   * Per face of the mesh's face set: an internal face's rank (0 the most
   * important), NoRank for a boundary face. A frame drawing |I| internal faces
   * draws those with a rank below |I|.
   */
  const std::vector<uint32_t>& GetRanks() const { return this->Ranks; }
  /// The internal faces from most to least important.
  const std::vector<uint32_t>& GetOrder() const { return this->Order; }
  vtkIdType GetNumberOfInternalFaces() const { return static_cast<vtkIdType>(this->Order.size()); }
  /// Changes whenever the ranks do.
  vtkMTimeType GetRankVersion() const { return this->RankTime.GetMTime(); }

  ///@{
  /// Topology: the number of layers peeled, and each face's layer (0 the
  /// boundary, -1 a face no layer reached).
  vtkGetMacro(NumberOfLayers, int);
  const std::vector<int>& GetFaceLayers() const { return this->FaceLayers; }
  ///@}

  ///@{
  /// The last preprocessing (Update) and view ranking (UpdateView) times, and
  /// the bytes the ranking holds.
  vtkGetMacro(LastSeconds, double);
  vtkGetMacro(LastViewSeconds, double);
  size_t GetMemoryBytes() const;
  ///@}

  /// The 96 normal clusters: the cluster of a unit normal.
  static int NormalCluster(const double n[3]);
  /// The centre direction (unit) of a cluster.
  static void ClusterDirection(int cluster, double d[3]);
  static constexpr int NumberOfClusters = 96;

protected:
  vtkHAVSInternalFaceRanking() = default;
  ~vtkHAVSInternalFaceRanking() override = default;

private:
  vtkHAVSInternalFaceRanking(const vtkHAVSInternalFaceRanking&) = delete;
  void operator=(const vtkHAVSInternalFaceRanking&) = delete;

  void RankTopology(
    vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal, const ProgressCallback& progress);
  void RankField(vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal);
  void RankArea(vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal);
  void ClusterNormals(vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal);
  void RanksFromOrder();

  int Strategy = Area;
  unsigned int Seed = 5489u;

  size_t NumberOfFaces = 0;
  std::vector<uint32_t> Ranks;
  std::vector<uint32_t> Order;
  vtkTimeStamp RankTime;
  int NumberOfLayers = 0;
  std::vector<int> FaceLayers;
  // ViewAligned: the internal faces grouped by cluster (random order within).
  std::vector<uint32_t> ClusterStart; // NumberOfClusters + 1 offsets into ClusterFaces
  std::vector<uint32_t> ClusterFaces;
  std::array<int, NumberOfClusters> ClusterOrder{};
  bool ViewRanked = false;

  vtkMTimeType MeshVersion = 0;
  vtkMTimeType ScalarVersion = 0;
  int RankedStrategy = -1;
  unsigned int RankedSeed = 0;
  double LastSeconds = 0.0;
  double LastViewSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif
