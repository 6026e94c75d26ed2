#include "distributed/partition.hpp"

#include <zoltan.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace sph::distributed {

namespace {

// What Zoltan's query functions read: the particles this rank passed.
struct Query {
  const std::vector<float>* points = nullptr;
  const std::vector<float>* work = nullptr;
};

int objectCount(void* data, int* error) {
  *error = ZOLTAN_OK;
  return int(static_cast<Query*>(data)->points->size() / 3);
}

void objectList(void* data, int gidEntries, int lidEntries, ZOLTAN_ID_PTR globalIds,
                ZOLTAN_ID_PTR localIds, int weightDim, float* weights, int* error) {
  const Query& q = *static_cast<Query*>(data);
  const std::size_t n = q.points->size() / 3;
  (void)gidEntries;
  (void)lidEntries;
  // Zoltan needs global ids only to tell objects apart; the answer comes back by local id.
  for (std::size_t i = 0; i < n; ++i) {
    globalIds[i] = ZOLTAN_ID_TYPE(i);
    localIds[i] = ZOLTAN_ID_TYPE(i);
    if (weightDim > 0) weights[i] = q.work->empty() ? 1.0f : (*q.work)[i];
  }
  *error = ZOLTAN_OK;
}

int geometryDimension(void*, int* error) {
  *error = ZOLTAN_OK;
  return 3;
}

void geometry(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR localIds, int,
              double* coordinates, int* error) {
  const std::vector<float>& p = *static_cast<Query*>(data)->points;
  for (int k = 0; k < count; ++k)
    for (int c = 0; c < 3; ++c) coordinates[3 * k + c] = p[3 * std::size_t(localIds[k]) + c];
  *error = ZOLTAN_OK;
}

void initialiseZoltan() {
  static std::once_flag once;
  std::call_once(once, [] {
    float version = 0.0f;
    int argc = 0;
    if (Zoltan_Initialize(argc, nullptr, &version) != ZOLTAN_OK)
      throw std::runtime_error("Zoltan_Initialize failed");
  });
}

}  // namespace

const char* partitionMethodName(PartitionMethod method) {
  return method == PartitionMethod::Hsfc ? "hsfc" : "rcb";
}

struct GeometricPartitioner::Impl {
  Zoltan_Struct* zoltan = nullptr;
  Query query;
  int rank = 0;
  PartitionMethod method = PartitionMethod::Rcb;
  bool cut = false;  // assign has run
  // This rank's box of the kept RCB cuts: a point inside is its own, with no query.
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
};

GeometricPartitioner::GeometricPartitioner(const Communicator& comm, PartitionMethod method)
    : impl_(std::make_unique<Impl>()) {
  initialiseZoltan();
  impl_->rank = comm.rank();
  impl_->method = method;
  impl_->zoltan = Zoltan_Create(comm.handle());
  if (!impl_->zoltan) throw std::runtime_error("Zoltan_Create failed");
  Zoltan_Struct* z = impl_->zoltan;
  Zoltan_Set_Param(z, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(z, "LB_METHOD", method == PartitionMethod::Hsfc ? "HSFC" : "RCB");
  Zoltan_Set_Param(z, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(z, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(z, "OBJ_WEIGHT_DIM", "1");
  Zoltan_Set_Param(z, "RETURN_LISTS", "PARTS");
  // Within 1 % of the mean work: the step waits for the slowest rank.
  Zoltan_Set_Param(z, "IMBALANCE_TOL", "1.01");
  if (method == PartitionMethod::Rcb) Zoltan_Set_Param(z, "RCB_REUSE", "1");
  Zoltan_Set_Param(z, "KEEP_CUTS", "1");  // owners() asks where a moved particle belongs
  Zoltan_Set_Num_Obj_Fn(z, objectCount, &impl_->query);
  Zoltan_Set_Obj_List_Fn(z, objectList, &impl_->query);
  Zoltan_Set_Num_Geom_Fn(z, geometryDimension, &impl_->query);
  Zoltan_Set_Geom_Multi_Fn(z, geometry, &impl_->query);
}

GeometricPartitioner::~GeometricPartitioner() {
  Zoltan_Destroy(&impl_->zoltan);
}

std::vector<int> GeometricPartitioner::assign(const std::vector<float>& points,
                                              const std::vector<float>& work) {
  const std::size_t n = points.size() / 3;
  if (!work.empty() && work.size() != n)
    throw std::invalid_argument("GeometricPartitioner::assign: " + std::to_string(work.size()) +
                                " weights for " + std::to_string(n) + " particles");
  impl_->query = {&points, &work};
  int changes = 0, gidEntries = 0, lidEntries = 0, imports = 0, exports = 0;
  ZOLTAN_ID_PTR importGlobal = nullptr, importLocal = nullptr, exportGlobal = nullptr,
                exportLocal = nullptr;
  int *importProcs = nullptr, *importParts = nullptr, *exportProcs = nullptr,
      *exportParts = nullptr;
  const int status =
      Zoltan_LB_Partition(impl_->zoltan, &changes, &gidEntries, &lidEntries, &imports,
                          &importGlobal, &importLocal, &importProcs, &importParts, &exports,
                          &exportGlobal, &exportLocal, &exportProcs, &exportParts);
  if (status != ZOLTAN_OK)
    throw std::runtime_error("Zoltan_LB_Partition failed (code " + std::to_string(status) + ")");
  // RETURN_LISTS PARTS: every local object is listed in the export lists with its new part.
  std::vector<int> owner(n, impl_->rank);
  for (int k = 0; k < exports; ++k) owner[std::size_t(exportLocal[k])] = exportParts[k];
  Zoltan_LB_Free_Part(&importGlobal, &importLocal, &importProcs, &importParts);
  Zoltan_LB_Free_Part(&exportGlobal, &exportLocal, &exportProcs, &exportParts);
  impl_->cut = true;
  if (impl_->method == PartitionMethod::Rcb) {
    int dimensions = 0;
    Impl& m = *impl_;
    if (Zoltan_RCB_Box(m.zoltan, m.rank, &dimensions, &m.lo[0], &m.lo[1], &m.lo[2], &m.hi[0],
                       &m.hi[1], &m.hi[2]) != ZOLTAN_OK)
      throw std::runtime_error("Zoltan_RCB_Box failed");
  }
  return owner;
}

std::vector<int> GeometricPartitioner::owners(const std::vector<float>& points) const {
  const Impl& m = *impl_;
  if (!m.cut) throw std::logic_error("GeometricPartitioner::owners: no partition yet (assign)");
  const std::size_t n = points.size() / 3;
  std::vector<int> owner(n, m.rank);
  for (std::size_t i = 0; i < n; ++i) {
    double p[3] = {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
    // A point on the box's face stays: the partition may have split a plane of particles
    // lying on a cut (a lattice's), and the cut alone would hand the whole plane to one side.
    const bool inside = m.method == PartitionMethod::Rcb && m.lo[0] <= p[0] && p[0] <= m.hi[0] &&
                        m.lo[1] <= p[1] && p[1] <= m.hi[1] && m.lo[2] <= p[2] && p[2] <= m.hi[2];
    if (inside) continue;
    int rank = 0, part = 0;
    if (Zoltan_LB_Point_PP_Assign(m.zoltan, p, &rank, &part) != ZOLTAN_OK)
      throw std::runtime_error("Zoltan_LB_Point_PP_Assign failed");
    owner[i] = part;
  }
  return owner;
}

}  // namespace sph::distributed
