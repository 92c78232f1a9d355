/*
    pingPong: the time one message of b bytes takes between two MPI ranks,
    for the latency (alpha) and the time per byte (beta) of the scaling model
    of benchmarks/parallel/scalingModel.

    Rank 0 sends b bytes to rank 1, which sends them back; the one-way time is
    half the round trip. For each size: a warm-up, then `repeats` timed round
    trips; prints "bytes,seconds" with the median one-way time.

    Usage: mpirun -np 2 pingPong [repeats]
*/
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int compare(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int rank = 0, size = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const int repeats = argc > 1 ? atoi(argv[1]) : 50;
    if (size != 2 || repeats < 1)
    {
        if (rank == 0)
        {
            fprintf(stderr, "pingPong: needs exactly 2 ranks (got %d) and repeats >= 1 (got %d)\n",
                    size, repeats);
        }
        MPI_Finalize();
        return 1;
    }
    const long largest = 1L << 24;
    char* buffer = malloc(largest);
    double* times = malloc(sizeof(double)*repeats);
    memset(buffer, 1, largest);
    if (rank == 0)
    {
        printf("bytes,seconds\n");
    }
    for (long bytes = 8; bytes <= largest; bytes *= 4)
    {
        for (int r = -1; r < repeats; ++r)
        {
            MPI_Barrier(MPI_COMM_WORLD);
            const double start = MPI_Wtime();
            if (rank == 0)
            {
                MPI_Send(buffer, (int)bytes, MPI_BYTE, 1, 0, MPI_COMM_WORLD);
                MPI_Recv(buffer, (int)bytes, MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            }
            else
            {
                MPI_Recv(buffer, (int)bytes, MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Send(buffer, (int)bytes, MPI_BYTE, 0, 0, MPI_COMM_WORLD);
            }
            if (r >= 0)
            {
                times[r] = 0.5*(MPI_Wtime() - start);
            }
        }
        qsort(times, repeats, sizeof(double), compare);
        if (rank == 0)
        {
            printf("%ld,%.6e\n", bytes, times[repeats/2]);
        }
    }
    free(times);
    free(buffer);
    MPI_Finalize();
    return 0;
}
