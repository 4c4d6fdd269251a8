// The ranks of a run and what they say to each other (Documentation/Architecture.md "Parallel").
//
// One interface, two implementations: MPI_COMM_WORLD when the program was started by mpirun
// (and the build has MPI, TALUS_WITH_MPI), and a single rank otherwise. The domain split
// (Parallel/DomainSplit.h) is written once against this interface, so a build without MPI
// compiles the same code, and a run without mpirun never initialises MPI.
// Every call is collective: all ranks make it, in the same order.
#pragma once

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace talus {

using Bytes = std::vector<char>;

class Communicator {
public:
    virtual ~Communicator() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;

    enum class Reduction { sum, max, min };
    // Replaces values[k] by the reduction over ranks of values[k], element by element.
    virtual void allReduce(double* values, int count, Reduction reduction) = 0;
    double sum(double x) { allReduce(&x, 1, Reduction::sum); return x; }
    double max(double x) { allReduce(&x, 1, Reduction::max); return x; }

    // All to all: outgoing[r] goes to rank r; returns what rank r sent here in element r.
    virtual std::vector<Bytes> exchange(const std::vector<Bytes>& outgoing) = 0;
    // Point to point between partners that know of each other and of the sizes: outgoing[k] goes
    // to sendTo[k]; incoming[k], sized by the caller, is filled from receiveFrom[k].
    void exchangeWith(const std::vector<int>& sendTo, const std::vector<Bytes>& outgoing,
                      const std::vector<int>& receiveFrom, std::vector<Bytes>& incoming) {
        startExchangeWith(sendTo, outgoing, receiveFrom, incoming);
        finishExchange();
    }
    // The same in two halves, so that other work (a collective too) runs while the messages
    // travel: start posts the receives and sends and returns at once; finish waits for them. In
    // between, outgoing and incoming must stay as they are; one exchange at a time.
    virtual void startExchangeWith(const std::vector<int>& sendTo, const std::vector<Bytes>& outgoing,
                                   const std::vector<int>& receiveFrom, std::vector<Bytes>& incoming) = 0;
    virtual void finishExchange() = 0;
    // Every rank's bytes, in rank order, on every rank.
    virtual std::vector<Bytes> allGather(const Bytes& mine) = 0;
    // Every rank's bytes, in rank order, on rank 0 (empty elsewhere).
    virtual std::vector<Bytes> gatherToRoot(const Bytes& mine) = 0;
    // Ends every rank of the run at once (for an error that only some ranks saw).
    [[noreturn]] virtual void abort(int code) = 0;
};

// The world of this process: MPI's when started by mpirun with an MPI build, else a single rank.
// Initialises MPI on first use and finalises it at exit.
Communicator& worldCommunicator();
// A single rank, whatever the launch (for tests and tools that must not talk to other ranks).
Communicator& singleRankCommunicator();

// Appending plain values to bytes and reading them back in the same order.
class Packer {
public:
    explicit Packer(Bytes& out) : out_(out) {}
    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T> || std::is_standard_layout_v<T>);
        const std::size_t at = out_.size();
        out_.resize(at + sizeof(T));
        std::memcpy(out_.data() + at, &value, sizeof(T));
    }

private:
    Bytes& out_;
};

class Unpacker {
public:
    explicit Unpacker(const Bytes& in) : in_(in) {}
    template <class T>
    T get() {
        T value;
        std::memcpy(static_cast<void*>(&value), in_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    bool atEnd() const { return at_ >= in_.size(); }

private:
    const Bytes& in_;
    std::size_t at_ = 0;
};

}  // namespace talus
