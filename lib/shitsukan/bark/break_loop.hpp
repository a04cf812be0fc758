// shitsukan/bark/break_loop.hpp — hirota1998 §3.1: the one loop both bark models crack with:
// take the next break, apply it, re-solve around it (relax), update the events it moved.
//
// Manual
//   SpringNetwork net;                                  // one spring under growth, as in
//   net.dim = 2;                                        // spring_network.hpp's manual
//   net.X = {{0, 0, 0}, {1, 0, 0}};
//   net.k_anchor = {1.0f, 1.0f};
//   BarkSpring spring;
//   spring.i = 0;  spring.j = 1;  spring.n = {1, 0, 0};  spring.l0 = 1;  spring.k = 10;
//   spring.growth_rate = 0.01f;  spring.eps_c = 0.05f;  spring.key = 1;
//   net.springs = {spring};
//   Status s = finalize_network(net);
//   struct OneSpring {                                  // a model: what the loop asks of it
//       SpringNetwork* net;
//       float value(std::uint32_t s) const {            // the next-event order: here eps_c / E
//           const float E = strain_rate(*net, s);
//           return net->springs[s].intact() && E > 0 ? net->springs[s].eps_c / E : 1e30f;
//       }
//       bool due(float v) const { return v <= 200.0f; }  // events up to t = 200
//       float apply(std::uint32_t s, float v, std::vector<std::uint32_t>& seeds) {
//           break_spring(*net, s, v);                   // break it; re-solve from its ends
//           seeds = {net->springs[s].i, net->springs[s].j};
//           return v;                                   // the event's time
//       }
//       void affected(const std::vector<std::uint32_t>&, AffectedItems& add) const {
//           add(0);                                     // items a moved node may change
//       }
//   };
//   OneSpring model{&net};
//   BreakLoop loop;
//   if (s) s = solve_full(net, 1e-6f, 1000);
//   if (s) loop.load(1, [](std::uint32_t) { return std::uint64_t(1); }, model);
//   int events = 0;
//   BreakObserver watch;                                // optional: sees every event in order
//   watch.on_event = [](const BreakLoopEvent&, const SpringNetwork&, void* user) {
//       ++*static_cast<int*>(user);
//   };
//   watch.user = &events;
//   if (s) s = loop.run(net, model, 1e-6f, watch);      // events == 1, at t = 0.05·21 / 0.01 = 105
//   return s;
//
// The paper breaks a spring "when its elongation passes its critical value" (§3.1) and lets the
// layer settle; both models here (crack_events.hpp: the two-layer cylinder in continuous time;
// layered_bark.hpp: the four-layer bark in steps) do that with this loop:
//   1. the next event is the item with the smallest value in an EventTree (event_tree.hpp: ties
//      to the smaller canonical key), if the model says it is due (its time <= T, or its ratio
//      to the threshold > 1);
//   2. the model applies it (breaks the spring, or debonds shear springs) and names the nodes to
//      re-solve from, in canonical order;
//   3. relax (spring_network.hpp) re-solves the neighbourhood from them;
//   4. the items the model says the touched nodes affect get their values recomputed; only the
//      changed leaves are re-sorted, so the tree always equals a fresh one built from every value.
// An observer, if given, sees each event after its re-solve (W is then the field valid from the
// event to the next one): the events in the order applied, one call each. The items, their
// values and what an event does are the model's; the order, the re-solve and the bookkeeping
// are this loop's, once.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

#include "shitsukan/bark/event_tree.hpp"
#include "shitsukan/bark/spring_network.hpp"
#include "shitsukan/core/status.hpp"

namespace shitsukan {

// One event as an observer sees it, after its re-solve.
struct BreakLoopEvent {
    int index = 0;               // 0, 1, 2, ... over the loop's life, in the order applied
    std::uint32_t item = 0;      // the model's item (crack_events: a spring; layered_bark: a
                                 // spring of either layer, or a node's shear tie)
    float value = 0;             // its value in the tree when it was taken
    float t = 0;                 // the model's time of the event
    const std::uint32_t* seeds = nullptr;    // the nodes the re-solve started from
    int seed_count = 0;
    const std::uint32_t* touched = nullptr;  // the nodes the re-solve updated
    int touched_count = 0;
};

struct BreakObserver {
    void (*on_event)(const BreakLoopEvent& event, const SpringNetwork& net, void* user) = nullptr;
    void* user = nullptr;
};

// What a model's affected() fills: each item once, however often it is named.
class AffectedItems {
public:
    AffectedItems(std::vector<std::uint32_t>& items, std::vector<std::uint8_t>& mark)
        : items_(items), mark_(mark) {
        items_.clear();
    }
    void operator()(std::uint32_t i) {
        if (mark_[i]) return;
        mark_[i] = 1;
        items_.push_back(i);
    }

private:
    std::vector<std::uint32_t>& items_;
    std::vector<std::uint8_t>& mark_;
};

class BreakLoop {
public:
    // Every item's value: a fresh tree the first time (or for another item count), else only
    // the leaves whose value changed bit for bit are re-sorted (the tree equals a fresh one).
    template <class Model>
    void load(int items, std::function<std::uint64_t(std::uint32_t)> key, const Model& model) {
        if (tree_.size() != items) {
            tree_ = EventTree(std::size_t(items), std::move(key));
            std::vector<float> v(static_cast<std::size_t>(items));
            for (int i = 0; i < items; ++i) v[std::size_t(i)] = model.value(std::uint32_t(i));
            tree_.set_all(v.data());
            mark_.assign(std::size_t(items), 0);
            return;
        }
        dirty_.clear();
        dirty_values_.clear();
        for (int i = 0; i < items; ++i) {
            const float v = model.value(std::uint32_t(i)), old = tree_.time(std::uint32_t(i));
            if (std::memcmp(&v, &old, sizeof v) != 0)
                dirty_.push_back(std::uint32_t(i)), dirty_values_.push_back(v);
        }
        tree_.set_many(dirty_, dirty_values_);
    }

    // Applies events while the model says the next one is due. At most items + 1 events per
    // call (each breaks something for good, or the model is inconsistent: not_supported).
    template <class Model>
    Status run(SpringNetwork& net, Model& model, float tol, const BreakObserver& observer = {}) {
        for (int guard = 0; guard <= tree_.size(); ++guard) {
            const std::uint32_t top = tree_.top();
            const float value = tree_.time(top);
            if (!model.due(value)) return Status::success();
            seeds_.clear();
            const float t = model.apply(top, value, seeds_);
            touched_.clear();
            SHITSUKAN_TRY(relax(net, seeds_.data(), int(seeds_.size()), tol, &touched_));
            update(model, top);
            if (observer.on_event) {
                BreakLoopEvent e;
                e.index = events_, e.item = top, e.value = value, e.t = t;
                e.seeds = seeds_.data(), e.seed_count = int(seeds_.size());
                e.touched = touched_.data(), e.touched_count = int(touched_.size());
                observer.on_event(e, net, observer.user);
            }
            ++events_;
        }
        return Status::error(StatusCode::not_supported,
                             "break loop: more than %d events in one call (a model whose events "
                             "break nothing)",
                             tree_.size() + 1);
    }

    const EventTree& tree() const { return tree_; }
    int events() const { return events_; }  // applied so far, over every run

private:
    // Step 4: the taken item and every item the touched nodes affect, each recomputed once.
    template <class Model>
    void update(const Model& model, std::uint32_t taken) {
        AffectedItems add(dirty_, mark_);
        add(taken);
        model.affected(touched_, add);
        dirty_values_.clear();
        for (std::uint32_t i : dirty_) mark_[i] = 0, dirty_values_.push_back(model.value(i));
        tree_.set_many(dirty_, dirty_values_);
    }

    EventTree tree_;
    std::vector<std::uint32_t> seeds_, touched_, dirty_;
    std::vector<float> dirty_values_;
    std::vector<std::uint8_t> mark_;
    int events_ = 0;
};

}  // namespace shitsukan
