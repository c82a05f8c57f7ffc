// PartList: the parts of a flattened object statement, shared between copies until one of them changes them.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "scene/object.h"

namespace wardray::parser {

using scene::Object;

/// One shape of a (flattened) object with whether it carries its own texture.
struct ObjectPart {
    Object object;
    bool has_texture = false;
};

/// The objects a copy of `object` creates: every node of its CSG tree and its clipping and bounding objects,
/// counted without recursion (a tree a loop nested deeply must not overflow the stack).
std::size_t object_count(const Object& object);

/// The parts of an object statement in their order. Copying a list is O(1): both copies share the parts as an
/// immutable chain of chunks (each chunk the parts one statement added after those of the chunk before it), so
/// `#declare U = union { object { U } sphere { ... } }` repeated N times costs O(N), not O(N^2). The first call
/// that reads parts one by one or changes them gives the list parts of its own (once: the chain's parts, copied
/// where other lists share them).
class PartList {
public:
    using iterator = std::vector<ObjectPart>::iterator;
    using const_iterator = std::vector<ObjectPart>::const_iterator;

    PartList() = default;
    /// Shares `other`'s parts (moving `other`'s own ones into a chunk both then share).
    PartList(const PartList& other);
    PartList& operator=(const PartList& other);
    PartList(PartList&&) noexcept = default;
    PartList& operator=(PartList&&) noexcept = default;
    ~PartList() = default;

    std::size_t size() const { return shared_size() + m_own.size(); }
    bool empty() const { return size() == 0; }
    /// The objects a copy of every part creates (see object_count), from counts the chunks keep.
    std::size_t objects() const;
    /// The objects of the parts still shared (0 once the list has parts of its own).
    std::size_t shared_objects() const;
    /// True while some parts are shared with other lists (reading them one by one copies them first).
    bool shared() const { return m_shared != nullptr; }
    /// Whether some part, at any depth, has a nonzero interior id.
    bool any_interior_id() const;

    // Reading parts one by one: the list owns them first.
    iterator begin() { return own().begin(); }
    iterator end() { return own().end(); }
    const_iterator begin() const { return own().begin(); }
    const_iterator end() const { return own().end(); }
    ObjectPart& front() { return own().front(); }
    const ObjectPart& front() const { return own().front(); }
    ObjectPart& back() { return own().back(); }
    ObjectPart& operator[](std::size_t i) { return own()[i]; }
    const ObjectPart& operator[](std::size_t i) const { return own()[i]; }

    void push_back(ObjectPart part) { own().push_back(std::move(part)); }
    void clear() {
        m_shared.reset();
        m_own.clear();
    }
    /// Appends every part of `other` after this list's own; an empty list takes `other` whole, in O(1).
    void append(PartList&& other);

private:
    struct Chunk;
    std::size_t shared_size() const;
    /// The parts as a vector of this list's own, the first time moving the parts of the chain's links no other
    /// list holds into it and copying the rest.
    std::vector<ObjectPart>& own() const;
    /// Moves the own parts into a new chunk on top of the shared chain (so copies can share them).
    void freeze() const;

    // Logically const: which of the two holds a part never changes what the list means.
    mutable std::shared_ptr<const Chunk> m_shared;  ///< the earlier parts, shared and immutable
    mutable std::vector<ObjectPart> m_own;          ///< the parts after them, this list's own
};

}  // namespace wardray::parser
