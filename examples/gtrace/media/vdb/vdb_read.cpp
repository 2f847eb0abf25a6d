// vdb_read.cpp - gtrace-vdb, the grid reader of gtrace's grid media (vdb_protocol.h): reads one float grid of an
// OpenVDB file under limits on its own address space, CPU time and output size, and writes its dense copy.
//
// The bound on the dense copy is checked twice before it is made: on the bounding box the file's metadata states
// (before the grid's tree is read) and on the bounding box of the active voxels the tree has (after it is read, so
// a file whose metadata understates its grid is refused, naming both). OpenVDB is not hardened against hostile
// files: a crash, a hang or an allocation beyond the limit ends this process only, and gtrace reports it.
#include "../vdb_protocol.h"

#include <openvdb/openvdb.h>
#include <openvdb/io/File.h>

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

/** The reader's CPU time, in seconds: reading and copying a grid of the largest accepted size takes far less. */
constexpr rlim_t cpu_seconds = 120;

bool write_all(const void *data, size_t n)
{
    const char *p = static_cast<const char *>(data);
    while (n > 0) {
        ssize_t w = write(1, p, n);
        if (w <= 0)
            return false;
        p += w;
        n -= static_cast<size_t>(w);
    }
    return true;
}

int refuse(const std::string &why)
{
    VdbReply r{};
    r.magic = VDB_REPLY_MAGIC;
    r.status = 1;
    std::snprintf(r.message, sizeof r.message, "%s", why.c_str());
    return write_all(&r, sizeof r) ? 0 : 1;
}

/** Voxels of a box, or -1 when it is empty or its extent does not fit in 32 bits. */
long long box_voxels(const openvdb::Coord &lo, const openvdb::Coord &hi)
{
    long long n = 1;
    for (int a = 0; a < 3; a++) {
        long long d = static_cast<long long>(hi[a]) - lo[a] + 1;
        if (d < 1 || d > 0x7fffffffLL)
            return -1;
        n = n > (1LL << 62) / d ? (1LL << 62) : n * d;
    }
    return n;
}

std::string box_text(const openvdb::Coord &lo, const openvdb::Coord &hi)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, "[%d,%d,%d]..[%d,%d,%d]", lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
    return buf;
}

int read_grid(const char *path, const char *name, long long max_voxels)
{
    openvdb::io::File file(path);
    file.open(false); // no delayed loading: the file is read now, under this process's limits
    if (!file.hasGrid(name)) {
        std::string names;
        for (auto it = file.beginName(); it != file.endName(); ++it)
            names += (names.empty() ? "" : ", ") + it.gridName();
        return refuse("has no grid '" + std::string(name) + "' (it has: " + (names.empty() ? "none" : names) + ")");
    }
    openvdb::GridBase::Ptr meta = file.readGridMetadata(name);
    const openvdb::Name type = meta->type();
    if (type != openvdb::FloatGrid::gridType())
        return refuse("grid '" + std::string(name) + "' holds " + type + ", not float values (a density)");
    bool stated = false;
    openvdb::Coord smin, smax;
    auto mmin = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    auto mmax = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    if (mmin && mmax) {
        smin = openvdb::Coord(mmin->value());
        smax = openvdb::Coord(mmax->value());
        stated = true;
        long long n = box_voxels(smin, smax);
        if (n > max_voxels)
            return refuse("grid '" + std::string(name) + "' states a bounding box " + box_text(smin, smax) + " of " +
                          std::to_string(n) + " voxels, more than the " + std::to_string(max_voxels) +
                          " its dense copy may have (the memory budget's room, at most 2^30)");
    }
    openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
    file.close();
    if (!grid)
        return refuse("grid '" + std::string(name) + "' cannot be read as float values");
    if (!grid->transform().isLinear())
        return refuse("grid '" + std::string(name) + "' has a non-linear transform (" +
                      grid->transform().mapType() + "); only affine placements are supported");
    const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
    VdbReply r{};
    r.magic = VDB_REPLY_MAGIC;
    r.active_voxels = grid->activeVoxelCount();
    if (box.empty())
        return refuse("grid '" + std::string(name) + "' has no active voxels");
    if (stated && !(box.min().x() >= smin.x() && box.min().y() >= smin.y() && box.min().z() >= smin.z() &&
                    box.max().x() <= smax.x() && box.max().y() <= smax.y() && box.max().z() <= smax.z()))
        return refuse("grid '" + std::string(name) + "' lies about its extent: its metadata states " +
                      box_text(smin, smax) + ", its voxels span " + box_text(box.min(), box.max()));
    long long n = box_voxels(box.min(), box.max());
    if (n < 0 || n > max_voxels)
        return refuse("grid '" + std::string(name) + "' spans " + box_text(box.min(), box.max()) + ", " +
                      std::to_string(n) + " voxels, more than the " + std::to_string(max_voxels) +
                      " its dense copy may have (the memory budget's room, at most 2^30)");
    const openvdb::Mat4d m = grid->transform().baseMap()->getAffineMap()->getMat4();
    for (int row = 0; row < 3; row++) { // OpenVDB multiplies row vectors: world = (i, j, k, 1) * m
        for (int col = 0; col < 3; col++)
            r.index_to_world[row * 4 + col] = m(col, row);
        r.index_to_world[row * 4 + 3] = m(3, row);
    }
    for (int a = 0; a < 3; a++) {
        r.min[a] = box.min()[a];
        r.dims[a] = box.max()[a] - box.min()[a] + 1;
    }
    if (!write_all(&r, sizeof r))
        return 1;
    auto acc = grid->getConstAccessor();
    std::vector<float> row(static_cast<size_t>(r.dims[0]));
    for (int k = 0; k < r.dims[2]; k++)
        for (int j = 0; j < r.dims[1]; j++) {
            for (int i = 0; i < r.dims[0]; i++)
                row[i] = acc.getValue(openvdb::Coord(r.min[0] + i, r.min[1] + j, r.min[2] + k));
            if (!write_all(row.data(), row.size() * sizeof(float)))
                return 1;
        }
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s FILE GRID MAX_VOXELS MAX_BYTES (gtrace starts it for its grid media)\n",
                     argv[0]);
        return 2;
    }
    const long long max_voxels = std::atoll(argv[3]);
    const unsigned long long max_bytes = std::strtoull(argv[4], nullptr, 10);
    struct rlimit none = {0, 0}, cpu = {cpu_seconds, cpu_seconds}, as = {max_bytes, max_bytes};
    setrlimit(RLIMIT_CORE, &none);
    setrlimit(RLIMIT_CPU, &cpu);
    if (max_bytes > 0)
        setrlimit(RLIMIT_AS, &as);
    try {
        openvdb::initialize();
        return read_grid(argv[1], argv[2], max_voxels);
    } catch (const std::bad_alloc &) {
        return refuse("reading it needs more memory than the reader's limit");
    } catch (const std::exception &e) {
        return refuse(std::string("is not a readable OpenVDB file: ") + e.what());
    } catch (...) {
        return refuse("is not a readable OpenVDB file");
    }
}
