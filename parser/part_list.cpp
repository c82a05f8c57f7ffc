// PartList: an immutable chain of chunks shared by copies, and the parts a list owns after it.
#include "parser/part_list.h"

#include <algorithm>
#include <iterator>

namespace wardray::parser {

namespace {

// Calls `visit` on every object of `o`'s tree (CSG children, clipping and bounding objects) without recursion.
template <typename Visit>
void walk_objects(const Object& o, Visit&& visit) {
    std::vector<const Object*> pending{&o};
    while (!pending.empty()) {
        const Object* at = pending.back();
        pending.pop_back();
        visit(*at);
        if (const auto* csg = std::get_if<scene::Csg>(&at->shape))
            for (const Object& child : csg->children) pending.push_back(&child);
        for (const Object& c : at->clipped_by) pending.push_back(&c);
        for (const Object& b : at->bounded_by) pending.push_back(&b);
    }
}

}  // namespace

std::size_t object_count(const Object& object) {
    std::size_t count = 0;
    walk_objects(object, [&](const Object&) { ++count; });
    return count;
}

/// Parts added after those of `prev`, with the totals of the chain down to here.
struct PartList::Chunk {
    std::shared_ptr<const Chunk> prev;
    std::vector<ObjectPart> parts;
    std::size_t size = 0;     ///< parts in this chunk and every one before it
    std::size_t objects = 0;  ///< object_count over those parts
    bool any_interior_id = false;

    Chunk() = default;
    Chunk(const Chunk&) = delete;
    Chunk& operator=(const Chunk&) = delete;
    // A chain as long as the loop that built it is released link by link, not by recursion down it.
    ~Chunk() {
        std::shared_ptr<const Chunk> next = std::move(prev);
        while (next && next.use_count() == 1) {
            std::shared_ptr<const Chunk> after = std::move(const_cast<Chunk&>(*next).prev);
            next = std::move(after);
        }
    }
};

PartList::PartList(const PartList& other) {
    other.freeze();
    m_shared = other.m_shared;
}

PartList& PartList::operator=(const PartList& other) {
    if (this == &other) return *this;
    other.freeze();
    m_shared = other.m_shared;
    m_own.clear();
    return *this;
}

std::size_t PartList::shared_size() const { return m_shared ? m_shared->size : 0; }

std::size_t PartList::shared_objects() const { return m_shared ? m_shared->objects : 0; }

std::size_t PartList::objects() const {
    std::size_t count = shared_objects();
    for (const ObjectPart& part : m_own) count += object_count(part.object);
    return count;
}

bool PartList::any_interior_id() const {
    if (m_shared && m_shared->any_interior_id) return true;
    bool any = false;
    for (const ObjectPart& part : m_own)
        walk_objects(part.object, [&](const Object& o) { any = any || o.interior_id != 0; });
    return any;
}

void PartList::freeze() const {
    if (m_own.empty()) return;
    auto chunk = std::make_shared<Chunk>();
    chunk->size = shared_size() + m_own.size();
    chunk->objects = shared_objects();
    chunk->any_interior_id = m_shared && m_shared->any_interior_id;
    for (const ObjectPart& part : m_own)
        walk_objects(part.object, [&](const Object& o) {
            ++chunk->objects;
            chunk->any_interior_id = chunk->any_interior_id || o.interior_id != 0;
        });
    chunk->prev = std::move(m_shared);
    chunk->parts = std::move(m_own);
    m_own.clear();
    m_shared = std::move(chunk);
}

std::vector<ObjectPart>& PartList::own() const {
    if (!m_shared) return m_own;
    // The chain holds the earliest parts at its end: gather the chunks, then copy their parts oldest first.
    std::vector<const Chunk*> chunks;
    for (const Chunk* c = m_shared.get(); c != nullptr; c = c->prev.get()) chunks.push_back(c);
    // The links no other list holds (from the top down to the first one another list shares, below which every
    // link is reachable from it) give their parts up instead of copying them: a chunk is created non-const.
    std::size_t unshared = 0;
    for (const std::shared_ptr<const Chunk>* link = &m_shared; *link && link->use_count() == 1; link = &(*link)->prev)
        ++unshared;
    std::vector<ObjectPart> all;
    all.reserve(size());
    for (std::size_t i = chunks.size(); i-- > 0;) {
        if (i < unshared) {
            std::vector<ObjectPart>& parts = const_cast<Chunk*>(chunks[i])->parts;
            all.insert(all.end(), std::make_move_iterator(parts.begin()), std::make_move_iterator(parts.end()));
        } else {
            all.insert(all.end(), chunks[i]->parts.begin(), chunks[i]->parts.end());
        }
    }
    all.insert(all.end(), std::make_move_iterator(m_own.begin()), std::make_move_iterator(m_own.end()));
    m_own = std::move(all);
    m_shared.reset();
    return m_own;
}

void PartList::append(PartList&& other) {
    if (empty()) {
        *this = std::move(other);
        return;
    }
    // Parts of `other`'s own go after this list's own ones; only a shared chain of `other` is copied.
    std::vector<ObjectPart>& theirs = other.m_shared ? other.own() : other.m_own;
    m_own.insert(m_own.end(), std::make_move_iterator(theirs.begin()), std::make_move_iterator(theirs.end()));
    other.clear();
}

}  // namespace wardray::parser
