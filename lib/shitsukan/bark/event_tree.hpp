// shitsukan/bark/event_tree.hpp — the next event among many: a min-tree with canonical ties.
//
// Manual
//   std::vector<std::uint64_t> keys = {30, 10, 20, 40};          // canonical keys: ties
//   auto key_of = [&](std::uint32_t i) { return keys[i]; };
//   std::size_t n = keys.size();
//   EventTree tree(n, [&](std::uint32_t i) { return key_of(i); });   // all leaves +inf
//   std::uint32_t i = 2;  float t = 0.5f;
//   tree.set(i, t);                                                  // O(log n) per change
//   tree.set_many({0, 1}, {0.5f, 0.7f});                             // many at once
//   std::uint32_t next = tree.top();  float when = tree.time(next);  // O(1): item 2 (key 20 < 30)
//
// Leaf i holds a time (or any value to minimise; +inf = never); an inner node holds the index
// of its smaller child. Equal times go to the smaller canonical key, never to the storage
// index, so the order of events does not depend on how items were numbered. set_many updates
// many leaves and recomputes each changed inner node once, level by level (a break disturbs
// thousands of springs; their paths to the root overlap).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace shitsukan {

class EventTree {
public:
    EventTree() = default;  // no items; assign a sized tree before use
    // n items; key(i) gives item i's canonical key (ties).
    EventTree(std::size_t n, std::function<std::uint64_t(std::uint32_t)> key) : key_(std::move(key)) {
        n_ = int(n);
        size_ = 1;
        while (size_ < n_) size_ *= 2;
        time_.assign(std::size_t(n_) + 1, std::numeric_limits<float>::infinity());  // slot n_: empty
        node_.assign(std::size_t(2 * size_), std::uint32_t(n_));
        mark_.assign(std::size_t(2 * size_), 0);
        for (int s = 0; s < n_; ++s) node_[std::size_t(size_ + s)] = std::uint32_t(s);
    }
    void set_all(const float* times) {
        for (int s = 0; s < n_; ++s) time_[std::size_t(s)] = times[s];
        for (int v = size_ - 1; v >= 1; --v) node_[v] = better(node_[2 * v], node_[2 * v + 1]);
    }
    void set(std::uint32_t s, float t) {
        time_[s] = t;
        for (int v = (size_ + int(s)) / 2; v >= 1; v /= 2)
            node_[v] = better(node_[2 * v], node_[2 * v + 1]);
    }
    // Many leaves at once: each changed inner node is recomputed once, level by level.
    void set_many(const std::vector<std::uint32_t>& springs, const std::vector<float>& times) {
        level_.clear();
        for (std::size_t k = 0; k < springs.size(); ++k) {
            time_[springs[k]] = times[k];
            const int v = (size_ + int(springs[k])) / 2;
            if (!mark_[std::size_t(v)]) mark_[std::size_t(v)] = 1, level_.push_back(v);
        }
        while (!level_.empty()) {
            next_.clear();
            for (int v : level_) {
                mark_[std::size_t(v)] = 0;
                node_[std::size_t(v)] = better(node_[std::size_t(2 * v)], node_[std::size_t(2 * v + 1)]);
                const int up = v / 2;
                if (up >= 1 && !mark_[std::size_t(up)]) mark_[std::size_t(up)] = 1, next_.push_back(up);
            }
            level_.swap(next_);
        }
    }
    std::uint32_t top() const { return node_[1]; }
    float time(std::uint32_t s) const { return time_[s]; }
    int size() const { return n_; }

private:
    std::uint32_t better(std::uint32_t a, std::uint32_t b) const {
        if (time_[a] < time_[b]) return a;
        if (time_[b] < time_[a]) return b;
        if (a == std::uint32_t(n_)) return b;
        if (b == std::uint32_t(n_)) return a;
        return key_(a) <= key_(b) ? a : b;
    }
    std::function<std::uint64_t(std::uint32_t)> key_;
    int n_ = 0, size_ = 1;
    std::vector<float> time_;
    std::vector<std::uint32_t> node_;
    std::vector<std::uint8_t> mark_;
    std::vector<int> level_, next_;
};


}  // namespace shitsukan
