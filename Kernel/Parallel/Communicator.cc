#include "Parallel/Communicator.h"

#include <cstdlib>

#include "Error.h"

namespace talus {

namespace {

class SingleRank final : public Communicator {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void allReduce(double*, int, Reduction) override {}
    std::vector<Bytes> exchange(const std::vector<Bytes>& outgoing) override { return outgoing; }
    void startExchangeWith(const std::vector<int>& sendTo, const std::vector<Bytes>&,
                           const std::vector<int>& receiveFrom, std::vector<Bytes>&) override {
        require(sendTo.empty() && receiveFrom.empty(), "a single rank has no partner to exchange with");
    }
    void finishExchange() override {}
    std::vector<Bytes> allGather(const Bytes& mine) override { return {mine}; }
    std::vector<Bytes> gatherToRoot(const Bytes& mine) override { return {mine}; }
    [[noreturn]] void abort(int code) override { std::exit(code); }
};

}  // namespace

Communicator& singleRankCommunicator() {
    static SingleRank single;
    return single;
}

#ifndef TALUS_HAS_MPI
Communicator& worldCommunicator() { return singleRankCommunicator(); }
#endif

}  // namespace talus
