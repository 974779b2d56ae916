// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TileDistribution.h (private)
/// The tiled band distributed over the ranks of a communicator
/// (Documentation/Octree.md, "Distributing the tiled band"), p4est's way for a
/// forest whose leaves are the tiles:
///  - every rank keeps the whole slot map (one int32 per 8^D nodes), in which a
///    tile another rank holds is Remote (TiledField.h);
///  - each slot has an owner (TileOwners.h: runs of the Morton order with equal
///    numbers of tiles); a rank computes on the tiles of its own slots only;
///  - it also holds ghost tiles, copies of the other ranks' tiles within
///    `depth` slots of its own (one layer: the reinitialisation's neighbours,
///    the energy's cells, the distance stencils, the points' stencils; more for
///    a step whose feet reach farther), refreshed from their owners by messages
///    to and from the neighbouring ranks only (Communicator::neighbourExchange;
///    migrations use one personalised all-to-all, Communicator::allToAllV);
///  - a rank that adds or frees a tile tells every rank (one gather per
///    iteration), so that every slot map stays the same;
///  - sums are added in the one-rank order (orderedSum), so the result does
///    not depend on the number of ranks, to the last bit.
/// One rank runs the same code: it owns every slot, so it holds no ghost, and
/// its exchanges and reductions are the serial communicator's copies.

#include "TileOwners.h"
#include "sltk/core/IndexBox.h"
#include "sltk/exec/Communicator.h"
#include "sltk/octree/TiledField.h"

#include <algorithm>
#include <array>
#include <bitset>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace sltk
{

/// The most ghost layers (slots) a step may ask for: its copies reach at
/// most MaxHalo = 32 nodes (TiledReconstruction.cxx), four tiles.
constexpr int MaxGhostLayers = 4;

/// N partial sums of one item (a tile, a block of tiles) and the key that
/// orders them (its slot or block index).
template <size_t N>
struct KeyedSums
{
  std::uint64_t Key = 0;
  std::array<double, N> Values{};
};

template <int D>
class TileDistribution
{
public:
  explicit TileDistribution(const Communicator& comm)
    : Comm(&comm)
  {
  }

  const Communicator& comm() const { return *this->Comm; }
  bool distributed() const { return this->Comm->size() > 1; }
  int rank() const { return this->Comm->rank(); }

  /// The owners of the field's slots; ghosts are then held again by holdGhosts().
  void setOwners(const TiledField<D>& field, std::vector<std::int32_t> owners)
  {
    this->Owners = std::move(owners);
    this->Zone = distanceToRank<D>(field.slotDims(), this->Owners, this->rank(), MaxGhostLayers + 1);
    this->HeldDepth = 1; // a new grid: one layer until a step asks for more
    this->PlanValid = false;
  }
  /// The owner of every slot when `weighted` (per slot) are the tiles to share out.
  std::vector<std::int32_t> balancedOwners(const TiledField<D>& field, const std::vector<std::uint8_t>& weighted) const
  {
    return mortonOwners<D>(field, weighted, this->Comm->size(), TileBlockEdge);
  }
  /// The slots holding a tile on some rank (this rank's tiles, ghosts and Remote slots).
  static std::vector<std::uint8_t> tileSlots(const TiledField<D>& field)
  {
    std::vector<std::uint8_t> tiles(static_cast<size_t>(field.slotCount()), 0);
    for (Index s = 0; s < field.slotCount(); ++s)
    {
      tiles[static_cast<size_t>(s)] = field.slot(s) >= 0 || field.slot(s) == TiledField<D>::Remote;
    }
    return tiles;
  }

  /// The owner of every slot.
  const std::vector<std::int32_t>& owners() const { return this->Owners; }
  bool ownsSlot(Index s) const { return this->Owners[static_cast<size_t>(s)] == this->rank(); }
  int ownerOf(Index s) const { return this->Owners[static_cast<size_t>(s)]; }
  bool owns(const TiledField<D>& field, std::int32_t id) const { return this->ownsSlot(field.tileSlot(id)); }

  /// The tiles of `tiles` this rank owns, in their order.
  std::vector<std::int32_t> owned(const TiledField<D>& field, const std::vector<std::int32_t>& tiles) const
  {
    std::vector<std::int32_t> mine;
    for (std::int32_t id : tiles)
    {
      if (this->owns(field, id))
      {
        mine.push_back(id);
      }
    }
    return mine;
  }

  /// The tiles of every rank (each counted by its owner).
  Index globalTileCount(const TiledField<D>& field) const
  {
    std::int64_t count = 0;
    for (std::int32_t id = 0; id < field.tileCount(); ++id)
    {
      count += this->owns(field, id) ? 1 : 0;
    }
    return this->Comm->allReduce(count, ReduceOp::Sum);
  }

  /// The tiles and the octree's leaves, as the hyper tree grid holds them
  /// (SLTKTiledGrid.h: TiledField::leafCount for a tile, one leaf for a slot
  /// without one), each counted by the slot's owner, in one pass and two
  /// reductions.
  struct StorageCounts
  {
    Index Tiles = 0;             ///< over every rank (globalTileCount)
    Index Leaves = 0;            ///< over every rank
    Index LargestRankLeaves = 0; ///< the most one rank owns
  };
  StorageCounts storageCounts(const TiledField<D>& field) const
  {
    std::int64_t mine[2] = { 0, 0 }; // tiles, leaves
    for (Index s = 0; s < field.slotCount(); ++s)
    {
      if (!this->ownsSlot(s))
      {
        continue;
      }
      const std::int32_t entry = field.slot(s);
      mine[0] += entry >= 0 ? 1 : 0;
      mine[1] += entry >= 0 ? field.leafCount(entry) : 1; // a slot without a tile: one leaf
    }
    const std::int64_t largest = this->Comm->allReduce(mine[1], ReduceOp::Max);
    this->Comm->allReduce(mine, 2, ReduceOp::Sum);
    return { mine[0], mine[1], largest };
  }

  /// The same status on every rank (the lowest failing rank's), with any
  /// internal error an exchange found.
  Status agree(const Status& local)
  {
    const Status mine = local.isOk() ? this->Broken : local;
    this->Broken = Status::ok();
    return this->Comm->agree(mine);
  }

  /// Slot changes of this rank's own slots: a tile there, or a side.
  enum class SlotState : std::int64_t
  {
    Tile = 0,
    Outside = 1,
    Inside = 2
  };
  void recordChange(std::vector<std::int64_t>& changes, Index slot, SlotState state) const
  {
    changes.push_back(slot * 4 + static_cast<std::int64_t>(state));
  }

  /// Every rank's `changes` (recordChange) applied to this rank's slot map:
  /// another rank's new tile is a ghost here when within the held depth of
  /// this rank's slots, else Remote; a freed one is its side (a ghost copy
  /// dropped: forget(remove) follows TiledField::removeTiles). Collective.
  template <class Forget>
  void shareChanges(TiledField<D>& field, const std::vector<std::int64_t>& changes, Forget&& forget)
  {
    this->PlanValid = false;
    const std::vector<std::int64_t> all = this->Comm->allGatherV(changes);
    std::vector<std::uint8_t> remove;
    std::vector<std::pair<Index, bool>> sides; // slots whose ghost tile goes, and their side
    for (const std::int64_t change : all)
    {
      const Index s = change / 4;
      const auto state = static_cast<SlotState>(change % 4);
      if (this->ownsSlot(s))
      {
        continue; // this rank's own change
      }
      const std::int32_t entry = field.slot(s);
      if (state == SlotState::Tile)
      {
        if (entry < 0 && entry != TiledField<D>::Remote)
        {
          if (this->Zone[static_cast<size_t>(s)] <= this->HeldDepth)
          {
            field.addTile(s); // at its side's +-gamma, as the owner's new tile
          }
          else
          {
            field.setRemote(s);
          }
        }
        continue;
      }
      const bool inside = state == SlotState::Inside;
      if (entry >= 0)
      {
        remove.resize(static_cast<size_t>(field.tileCount()), 0);
        remove[static_cast<size_t>(entry)] = 1;
        sides.emplace_back(s, inside);
      }
      else
      {
        field.setSide(s, inside);
      }
    }
    if (!remove.empty())
    {
      remove.resize(static_cast<size_t>(field.tileCount()), 0);
      field.removeTiles(remove);
      forget(remove);
      for (const auto& side : sides)
      {
        field.setSide(side.first, side.second);
      }
    }
  }

  /// Holds, as ghosts, exactly the other ranks' tiles within `depth` (<=
  /// MaxGhostLayers) slots of this rank's slots: new ones are allocated (their
  /// values come with the next exchange()), farther ones dropped.
  template <class Forget>
  void holdGhosts(TiledField<D>& field, int depth, Forget&& forget)
  {
    this->HeldDepth = depth;
    this->PlanValid = false;
    std::vector<std::uint8_t> remove;
    for (Index s = 0; s < field.slotCount(); ++s)
    {
      const std::int32_t entry = field.slot(s);
      const bool near = this->Zone[static_cast<size_t>(s)] <= depth;
      if (entry == TiledField<D>::Remote && near)
      {
        field.addTile(s);
      }
      else if (entry >= 0 && !near)
      {
        remove.resize(static_cast<size_t>(field.tileCount()), 0);
        remove[static_cast<size_t>(entry)] = TiledField<D>::RemoveToRemote;
      }
    }
    if (!remove.empty())
    {
      remove.resize(static_cast<size_t>(field.tileCount()), 0);
      field.removeTiles(remove);
      forget(remove);
    }
  }
  int heldDepth() const { return this->HeldDepth; }

  /// The ghosts' phi (and d with `withDistance`) from their owners: one
  /// message to and from each neighbouring rank (Communicator::neighbourExchange).
  /// Collective over the neighbours.
  void exchange(TiledField<D>& field, bool withDistance)
  {
    this->plan(field);
    const size_t tileBytes =
      sizeof(std::int64_t) + static_cast<size_t>(TiledField<D>::Nodes) * (withDistance ? 2 : 1) * sizeof(double);
    this->exchangeWithNeighbours([&](std::uint8_t) { return tileBytes; },
      [&](std::int32_t id, std::uint8_t, unsigned char* out) { this->pack(field, id, withDistance, out); },
      [&](std::int32_t id, std::uint8_t, const unsigned char* in) { this->unpack(field, id, withDistance, in); });
  }

  /// The ghosts' phi at the face layers next to this rank's slots only, all a
  /// pseudo-time step of the reinitialisation reads of them (its axis
  /// neighbours, TiledReinitialise.h): 1/8 of a tile a face. Collective over
  /// the neighbours.
  void exchangeFaces(TiledField<D>& field)
  {
    this->plan(field);
    constexpr size_t FaceBytes = static_cast<size_t>(TiledField<D>::Nodes / TileEdge) * sizeof(double);
    this->exchangeWithNeighbours([&](std::uint8_t faces) { return std::bitset<8>(faces).count() * FaceBytes; },
      [&](std::int32_t id, std::uint8_t faces, unsigned char* out)
      {
        const double* p = field.phi(id);
        auto* to = reinterpret_cast<double*>(out);
        forEachFaceNode(faces, [&](Index k) { *to++ = p[k]; });
      },
      [&](std::int32_t id, std::uint8_t faces, const unsigned char* in)
      {
        double* p = field.phi(id);
        const auto* from = reinterpret_cast<const double*>(in);
        forEachFaceNode(faces, [&](Index k) { p[k] = *from++; });
      });
  }

  /// Gives each of this rank's tiles to its owner in `owners` (the other
  /// ranks' tiles sent here are added, replacing a ghost copy), then makes
  /// `owners` the partition and holds the ghosts again. Collective.
  template <class Forget>
  void migrate(TiledField<D>& field, std::vector<std::int32_t> owners, Forget&& forget)
  {
    std::vector<std::vector<std::int32_t>> leaving(static_cast<size_t>(this->Comm->size()));
    std::vector<std::uint8_t> remove(static_cast<size_t>(field.tileCount()), 0);
    field.forEachTileInSlotOrder(
      [&](std::int32_t id)
      {
        const Index s = field.tileSlot(id);
        const int to = owners[static_cast<size_t>(s)];
        if (this->ownsSlot(s) && to != this->rank())
        {
          leaving[static_cast<size_t>(to)].push_back(id);
          remove[static_cast<size_t>(id)] = TiledField<D>::RemoveToRemote;
        }
      });
    const std::vector<unsigned char> incoming = sendWholeTiles(field, leaving, *this->Comm);
    field.removeTiles(remove);
    forget(remove);
    storeWholeTiles(field, incoming);
    this->setOwners(field, std::move(owners));
    this->holdGhosts(field, 1, forget); // a new partition: one layer
  }

  /// Sends the tiles `going[r]` whole (slot, phi and d) to rank r, in one
  /// all-to-all (migrate, gatherTiles); returns the tiles sent to this rank,
  /// for storeWholeTiles. Collective.
  static std::vector<unsigned char> sendWholeTiles(
    const TiledField<D>& field, const std::vector<std::vector<std::int32_t>>& going, const Communicator& comm)
  {
    std::vector<std::int64_t> counts(going.size(), 0);
    std::vector<unsigned char> send;
    for (size_t r = 0; r < going.size(); ++r)
    {
      counts[r] = static_cast<std::int64_t>(going[r].size() * WholeTileBytes);
      const size_t at = send.size();
      send.resize(at + going[r].size() * WholeTileBytes);
      unsigned char* out = send.data() + at;
      for (std::int32_t id : going[r])
      {
        out = pack(field, id, true, out);
      }
    }
    std::vector<unsigned char> incoming;
    std::vector<std::int64_t> received;
    comm.allToAllV(send.data(), counts, incoming, received);
    return incoming;
  }

  /// Stores the tiles of sendWholeTiles in their slots: over the copy held
  /// there (a ghost), or in a new tile.
  static void storeWholeTiles(TiledField<D>& field, const std::vector<unsigned char>& incoming)
  {
    for (size_t at = 0; at + WholeTileBytes <= incoming.size(); at += WholeTileBytes)
    {
      std::int64_t slot = 0;
      std::memcpy(&slot, incoming.data() + at, sizeof(slot));
      const std::int32_t id = field.slot(slot) >= 0 ? field.slot(slot) : field.addTile(slot);
      copyTileValues(field, id, true, incoming.data() + at + sizeof(slot));
    }
  }

  /// The sums over every rank's `items` (key, N values) added in the order of
  /// the keys, starting from `start` (the callers' are in key order: one rank
  /// adds its items in their order). Collective.
  template <size_t N>
  std::array<double, N> orderedSum(std::vector<KeyedSums<N>> items, std::array<double, N> start) const
  {
    items = this->Comm->allGatherV(items);
    std::stable_sort(items.begin(), items.end(), [](const auto& x, const auto& y) { return x.Key < y.Key; });
    for (const auto& item : items)
    {
      for (size_t k = 0; k < N; ++k)
      {
        start[k] += item.Values[k];
      }
    }
    return start;
  }

  double max(double value) const { return this->Comm->allReduce(value, ReduceOp::Max); }

private:
  /// Who sends what: this rank's tiles to each rank within the held depth of
  /// its slots, and its ghosts by owner, both in slot order.
  void plan(const TiledField<D>& field)
  {
    if (this->PlanValid && this->PlanGeneration == field.generation())
    {
      return;
    }
    const int ranks = this->Comm->size();
    this->Sends.assign(static_cast<size_t>(ranks), {});
    this->Receives.assign(static_cast<size_t>(ranks), {});
    this->SendFaces.assign(static_cast<size_t>(ranks), {});
    this->ReceiveFaces.assign(static_cast<size_t>(ranks), {});
    std::vector<std::uint8_t> to(static_cast<size_t>(ranks), 0);
    const auto& dims = field.slotDims();
    field.forEachTileInSlotOrder(
      [&](std::int32_t id)
      {
        const Index s = field.tileSlot(id);
        if (!this->ownsSlot(s))
        {
          const int owner = this->Owners[static_cast<size_t>(s)];
          this->Receives[static_cast<size_t>(owner)].push_back(id);
          this->ReceiveFaces[static_cast<size_t>(owner)].push_back(this->facesToward(field, id, this->rank()));
          return;
        }
        std::fill(to.begin(), to.end(), 0);
        const auto& t = field.tileOrigin(id);
        std::array<Index, D> lo{}, hi{};
        for (int a = 0; a < D; ++a)
        {
          lo[a] = std::max<Index>(t[a] - this->HeldDepth, 0);
          hi[a] = std::min<Index>(t[a] + this->HeldDepth, dims[a] - 1);
        }
        forEachIndexInBox<D>(lo, hi,
          [&](const std::array<Index, D>& u)
          { to[static_cast<size_t>(this->Owners[static_cast<size_t>(field.slotIndex(u))])] = 1; });
        for (int r = 0; r < ranks; ++r)
        {
          if (to[static_cast<size_t>(r)] && r != this->rank())
          {
            this->Sends[static_cast<size_t>(r)].push_back(id);
            this->SendFaces[static_cast<size_t>(r)].push_back(this->facesToward(field, id, r));
          }
        }
      });
    this->PlanValid = true;
    this->PlanGeneration = field.generation();
  }

  /// One exchange with the ranks of the plan: `bytes(faces)` is the size of a
  /// tile's part (`faces`: facesToward the receiver), `write(id, faces, out)`
  /// packs a tile this rank sends, `read(id, faces, in)` unpacks a ghost. A
  /// rank exchanges with every rank it shares tiles with, even when no byte
  /// goes (both sides know the plan).
  template <class Bytes, class Write, class Read>
  void exchangeWithNeighbours(Bytes&& bytes, Write&& write, Read&& read)
  {
    const size_t ranks = static_cast<size_t>(this->Comm->size());
    const auto offsets = [&](const std::vector<std::vector<std::uint8_t>>& faces)
    {
      std::vector<size_t> at(ranks + 1, 0);
      for (size_t r = 0; r < ranks; ++r)
      {
        at[r + 1] = at[r];
        for (std::uint8_t f : faces[r])
        {
          at[r + 1] += bytes(f);
        }
      }
      return at;
    };
    const std::vector<size_t> sendAt = offsets(this->SendFaces), receiveAt = offsets(this->ReceiveFaces);
    this->Buffer.resize(sendAt.back());
    this->Received.resize(receiveAt.back());
    std::vector<Communicator::Outgoing> out;
    std::vector<Communicator::Incoming> in;
    for (size_t r = 0; r < ranks; ++r)
    {
      size_t at = sendAt[r];
      for (size_t j = 0; j < this->Sends[r].size(); ++j)
      {
        write(this->Sends[r][j], this->SendFaces[r][j], this->Buffer.data() + at);
        at += bytes(this->SendFaces[r][j]);
      }
      if (!this->Sends[r].empty())
      {
        out.push_back({ static_cast<int>(r), this->Buffer.data() + sendAt[r], sendAt[r + 1] - sendAt[r] });
      }
      if (!this->Receives[r].empty())
      {
        in.push_back({ static_cast<int>(r), this->Received.data() + receiveAt[r], receiveAt[r + 1] - receiveAt[r] });
      }
    }
    if (!this->Comm->neighbourExchange(out, in))
    {
      this->fail("a neighbour sent fewer bytes of ghost tiles than this rank's plan expects");
    }
    for (size_t r = 0; r < ranks; ++r)
    {
      size_t at = receiveAt[r];
      for (size_t j = 0; j < this->Receives[r].size(); ++j)
      {
        read(this->Receives[r][j], this->ReceiveFaces[r][j], this->Received.data() + at);
        at += bytes(this->ReceiveFaces[r][j]);
      }
    }
  }

  /// Bit 2 a + side of the faces of tile `id` whose neighbouring slot (axis
  /// a, lower side 0, upper 1) `rank` owns.
  std::uint8_t facesToward(const TiledField<D>& field, std::int32_t id, int rank) const
  {
    std::uint8_t faces = 0;
    for (int a = 0; a < D; ++a)
    {
      for (int side = 0; side < 2; ++side)
      {
        std::array<Index, D> t = field.tileOrigin(id);
        t[a] += side ? 1 : -1;
        if (t[a] >= 0 && t[a] < field.slotDims()[a] && this->Owners[static_cast<size_t>(field.slotIndex(t))] == rank)
        {
          faces = static_cast<std::uint8_t>(faces | (1u << (2 * a + side)));
        }
      }
    }
    return faces;
  }

  /// Calls f(local node) for the nodes of the face layers `faces` of a tile
  /// (facesToward), face after face.
  template <class F>
  static void forEachFaceNode(std::uint8_t faces, F&& f)
  {
    constexpr Index Layer = TiledField<D>::Nodes / TileEdge;
    for (int face = 0; face < 2 * D; ++face)
    {
      if (!(faces >> face & 1u))
      {
        continue;
      }
      const int a = face / 2;
      const Index c = face % 2 ? TileEdge - 1 : 0;
      for (Index n = 0; n < Layer; ++n)
      {
        // n spreads over the other axes' bits; axis a's coordinate is c.
        const Index low = n & ((Index(1) << (TileBits * a)) - 1);
        const Index high = (n >> (TileBits * a)) << (TileBits * (a + 1));
        f(high | (c << (TileBits * a)) | low);
      }
    }
  }

  /// A tile's slot, phi and d (pack with withDistance).
  static constexpr size_t WholeTileBytes =
    sizeof(std::int64_t) + 2 * static_cast<size_t>(TiledField<D>::Nodes) * sizeof(double);

  /// Writes tile `id`'s slot, phi and (withDistance) d at `out`; returns the end.
  static unsigned char* pack(const TiledField<D>& field, std::int32_t id, bool withDistance, unsigned char* out)
  {
    const std::int64_t slot = field.tileSlot(id);
    std::memcpy(out, &slot, sizeof(slot));
    out += sizeof(slot);
    const size_t bytes = static_cast<size_t>(TiledField<D>::Nodes) * sizeof(double);
    std::memcpy(out, field.phi(id), bytes);
    out += bytes;
    if (withDistance)
    {
      std::memcpy(out, field.distance(id), bytes);
      out += bytes;
    }
    return out;
  }

  const unsigned char* unpack(TiledField<D>& field, std::int32_t id, bool withDistance, const unsigned char* in)
  {
    std::int64_t slot = 0;
    std::memcpy(&slot, in, sizeof(slot));
    in += sizeof(slot);
    if (slot != field.tileSlot(id))
    {
      this->fail("a ghost tile arrived for slot " + std::to_string(slot) + " where slot " +
        std::to_string(field.tileSlot(id)) + " was expected");
    }
    return copyTileValues(field, id, withDistance, in);
  }

  /// Reads tile `id`'s phi and (withDistance) d from `in` (pack's values after
  /// the slot); returns the end.
  static const unsigned char* copyTileValues(
    TiledField<D>& field, std::int32_t id, bool withDistance, const unsigned char* in)
  {
    const size_t bytes = static_cast<size_t>(TiledField<D>::Nodes) * sizeof(double);
    std::memcpy(field.phi(id), in, bytes);
    in += bytes;
    if (withDistance)
    {
      std::memcpy(field.distance(id), in, bytes);
      in += bytes;
    }
    return in;
  }

  void fail(const std::string& what)
  {
    if (this->Broken.isOk())
    {
      this->Broken =
        Status::numericalFailure("the distributed tiled band lost its ghost plan (an internal error): " + what);
    }
  }

  const Communicator* Comm;
  std::vector<std::int32_t> Owners;
  std::vector<std::uint8_t> Zone; ///< per slot: distance to this rank's slots (capped)
  int HeldDepth = 1;
  bool PlanValid = false;           ///< false when the owners or the held depth changed
  std::uint64_t PlanGeneration = 0; ///< the field's tiles the plan was made for (TiledField::generation)
  std::vector<std::vector<std::int32_t>> Sends, Receives;
  std::vector<std::vector<std::uint8_t>> SendFaces, ReceiveFaces; ///< per tile of Sends / Receives: facesToward
  std::vector<unsigned char> Buffer, Received;
  Status Broken = Status::ok();
};

} // namespace sltk
