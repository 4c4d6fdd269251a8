// MPI_COMM_WORLD behind the Communicator interface (compiled only with TALUS_WITH_MPI).
#include <mpi.h>

#include <cstdlib>
#include <numeric>

#include "Error.h"
#include "Parallel/Communicator.h"

namespace talus {

namespace {

void check(int code, const char* what) {
    if (code != MPI_SUCCESS) throw Error(std::string("MPI error in ") + what);
}

int countOf(std::size_t bytes) {
    require(bytes < (1ull << 31), "an MPI message of " + std::to_string(bytes) + " bytes is too large (limit 2 GiB)");
    return static_cast<int>(bytes);
}

// Open MPI's shared-memory transport (vader) sends a message above 4 KB by a single copy from
// the sender's memory (CMA: two system calls per message) unless told to copy it through shared
// buffers. A step's ghost message is tens of KB (96 bytes a ghost); on virtual machines, where a
// system call is dear, the buffered copies made 2 ranks 10-15% faster at 3000 particles
// (Documentation/Parallel.md, "Speed"), and at 10^5 and more the exchange is a few percent of
// the step either way. A value the user set is kept; other MPI libraries ignore the variable.
void preferCopiesThroughSharedMemory() {
    setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", /*overwrite*/ 0);
}

class World final : public Communicator {
public:
    World() {
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) {
            preferCopiesThroughSharedMemory();
            MPI_Init(nullptr, nullptr);
            std::atexit([] {
                int finalised = 0;
                MPI_Finalized(&finalised);
                if (!finalised) MPI_Finalize();
            });
        }
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void allReduce(double* values, int count, Reduction reduction) override {
        const MPI_Op op = reduction == Reduction::sum ? MPI_SUM : reduction == Reduction::max ? MPI_MAX : MPI_MIN;
        check(MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, op, MPI_COMM_WORLD), "MPI_Allreduce");
    }

    std::vector<Bytes> exchange(const std::vector<Bytes>& outgoing) override {
        std::vector<int> sendCounts(size_), receiveCounts(size_), sendAt(size_), receiveAt(size_);
        for (int r = 0; r < size_; ++r) sendCounts[r] = countOf(outgoing[r].size());
        check(MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, MPI_COMM_WORLD),
              "MPI_Alltoall");
        Bytes send, receive;
        for (int r = 0; r < size_; ++r) {
            sendAt[r] = countOf(send.size());
            send.insert(send.end(), outgoing[r].begin(), outgoing[r].end());
        }
        std::size_t total = 0;
        for (int r = 0; r < size_; ++r) receiveAt[r] = countOf(total), total += receiveCounts[r];
        receive.resize(total);
        check(MPI_Alltoallv(send.data(), sendCounts.data(), sendAt.data(), MPI_BYTE, receive.data(),
                            receiveCounts.data(), receiveAt.data(), MPI_BYTE, MPI_COMM_WORLD),
              "MPI_Alltoallv");
        std::vector<Bytes> incoming(size_);
        for (int r = 0; r < size_; ++r)
            incoming[r].assign(receive.begin() + receiveAt[r], receive.begin() + receiveAt[r] + receiveCounts[r]);
        return incoming;
    }

    void startExchangeWith(const std::vector<int>& sendTo, const std::vector<Bytes>& outgoing,
                           const std::vector<int>& receiveFrom, std::vector<Bytes>& incoming) override {
        require(requests_.empty(), "startExchangeWith: the last exchange has not been finished");
        requests_.resize(sendTo.size() + receiveFrom.size());
        for (std::size_t k = 0; k < receiveFrom.size(); ++k)
            check(MPI_Irecv(incoming[k].data(), countOf(incoming[k].size()), MPI_BYTE, receiveFrom[k], tag,
                            MPI_COMM_WORLD, &requests_[k]),
                  "MPI_Irecv");
        for (std::size_t k = 0; k < sendTo.size(); ++k)
            check(MPI_Isend(outgoing[k].data(), countOf(outgoing[k].size()), MPI_BYTE, sendTo[k], tag, MPI_COMM_WORLD,
                            &requests_[receiveFrom.size() + k]),
                  "MPI_Isend");
    }
    void finishExchange() override {
        const int count = static_cast<int>(requests_.size());
        if (count > 0) check(MPI_Waitall(count, requests_.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
        requests_.clear();
    }

    std::vector<Bytes> allGather(const Bytes& mine) override { return gather(mine, /*everywhere*/ true); }
    std::vector<Bytes> gatherToRoot(const Bytes& mine) override { return gather(mine, false); }

    [[noreturn]] void abort(int code) override {
        MPI_Abort(MPI_COMM_WORLD, code);
        std::exit(code);
    }

private:
    static constexpr int tag = 7;

    std::vector<Bytes> gather(const Bytes& mine, bool everywhere) {
        const int count = countOf(mine.size());
        std::vector<int> counts(size_), at(size_);
        if (everywhere)
            check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
        else
            check(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
        std::size_t total = 0;
        for (int r = 0; r < size_; ++r) at[r] = countOf(total), total += counts[r];
        Bytes all(everywhere || rank_ == 0 ? total : 0);
        if (everywhere)
            check(MPI_Allgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE,
                                 MPI_COMM_WORLD),
                  "MPI_Allgatherv");
        else
            check(MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE, 0,
                              MPI_COMM_WORLD),
                  "MPI_Gatherv");
        std::vector<Bytes> result;
        if (!everywhere && rank_ != 0) return result;
        result.resize(size_);
        for (int r = 0; r < size_; ++r) result[r].assign(all.begin() + at[r], all.begin() + at[r] + counts[r]);
        return result;
    }

    int rank_ = 0, size_ = 1;
    std::vector<MPI_Request> requests_;  // of the exchange started and not yet finished
};

}  // namespace

// Started by mpirun (Open MPI sets OMPI_COMM_WORLD_SIZE, MPICH and others PMI_SIZE): the world;
// else a single rank without initialising MPI, so serial runs and unit tests never pay for it.
Communicator& worldCommunicator() {
    static Communicator& world = []() -> Communicator& {
        if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE")) return singleRankCommunicator();
        static World mpi;
        return mpi;
    }();
    return world;
}

}  // namespace talus
