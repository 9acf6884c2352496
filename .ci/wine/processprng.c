/*
 * A stand-in for Windows 10's bcryptprimitives.dll, for the Wine prefix of
 * the Windows test only (never shipped): Rust's standard library draws its
 * random numbers from ProcessPrng, which Debian 12's Wine 8.0 lacks.
 * ProcessPrng here fills the buffer from advapi32's RtlGenRandom
 * (SystemFunction036), which Wine has.
 */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length)
{
    while (length > 0) {
        ULONG chunk = length > 0x40000000 ? 0x40000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) {
            return FALSE;
        }
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
