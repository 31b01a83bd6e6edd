!> Counter-based random numbers for Monte Carlo campaigns.
!!
!! Every random number of a campaign is a pure function of (seed, case id, parameter index,
!! draw counter), so a case's inputs never depend on how many ranks run the campaign or in which
!! order cases are handed out. The generator is SplitMix64 (Steele, Lea & Flood, OOPSLA 2014):
!!
!!     next(x) = mix(x + gamma),  gamma = 0x9E3779B97F4A7C15
!!     mix(z)  : z = (z xor z>>30) * 0xBF58476D1CE4E5B9; z = (z xor z>>27) * 0x94D049BB133111EB;
!!               z xor z>>31
!!
!! and the 64-bit key of draw d of parameter j in case k is
!!
!!     h0 = mix(seed + gamma)
!!     h1 = mix((h0 xor k) + gamma)
!!     h2 = mix((h1 xor j) + gamma)
!!     h  = mix((h2 xor d) + gamma)
!!
!! (all arithmetic modulo 2**64, >> a logical shift). A uniform deviate in [0, 1) is
!! (h >> 11) * 2**-53. docs/campaign.md documents the same recipe.
!!
!! Fortran has no unsigned integers and signed overflow is not defined, so the 64-bit words are
!! held as bit patterns in integer(int64) and added and multiplied through 32- and 16-bit pieces
!! whose products never overflow. The results are exact and identical on every processor.
module landyn_campaign_rng
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp, pi
  use landyn_status, only: STAT_FAILED, STAT_OK
  implicit none
  private

  public :: splitmix64_next, splitmix64_mix, add64, mul64
  public :: case_key, case_uniform, case_normal, case_truncated_normal

  integer(int64), parameter :: gamma64 = -7046029254386353131_int64  !! 0x9E3779B97F4A7C15 [-]
  integer(int64), parameter :: mul1 = -4658895280553007687_int64     !! 0xBF58476D1CE4E5B9 [-]
  integer(int64), parameter :: mul2 = -7723592293110705685_int64     !! 0x94D049BB133111EB [-]
  integer(int64), parameter :: mask16 = 65535_int64                  !! 2**16 - 1 [-]

contains

  !> a + b modulo 2**64 (bit patterns).
  elemental function add64(a, b) result(c)
    integer(int64), intent(in) :: a, b  !! 64-bit words [-]
    integer(int64) :: c                 !! sum modulo 2**64 [-]
    integer(int64) :: lo, hi
    lo = ibits(a, 0, 32) + ibits(b, 0, 32)
    hi = ibits(a, 32, 32) + ibits(b, 32, 32) + ishft(lo, -32)
    c = ior(ishft(ibits(hi, 0, 32), 32), ibits(lo, 0, 32))
  end function add64

  !> a * b modulo 2**64 (bit patterns).
  elemental function mul64(a, b) result(c)
    integer(int64), intent(in) :: a, b  !! 64-bit words [-]
    integer(int64) :: c                 !! product modulo 2**64 [-]
    integer(int64) :: alo, ahi, blo, bhi, a0, a1, b0, b1, mid, t, lo32, hi32
    alo = ibits(a, 0, 32)
    ahi = ibits(a, 32, 32)
    blo = ibits(b, 0, 32)
    bhi = ibits(b, 32, 32)
    ! full 64-bit product of the low words from 16-bit pieces
    a0 = iand(alo, mask16)
    a1 = ishft(alo, -16)
    b0 = iand(blo, mask16)
    b1 = ishft(blo, -16)
    mid = a1*b0 + a0*b1                                  ! < 2**33
    t = a0*b0 + ishft(iand(mid, mask16), 16)             ! < 2**33
    lo32 = ibits(t, 0, 32)
    hi32 = a1*b1 + ishft(mid, -16) + ishft(t, -32)       ! < 2**33
    ! cross terms only matter modulo 2**32
    hi32 = ibits(hi32 + mullo32(ahi, blo) + mullo32(alo, bhi), 0, 32)
    c = ior(ishft(hi32, 32), lo32)
  end function mul64

  !> x * y modulo 2**32 for 0 <= x, y < 2**32.
  elemental function mullo32(x, y) result(p)
    integer(int64), intent(in) :: x, y  !! 32-bit words [-]
    integer(int64) :: p                 !! product modulo 2**32 [-]
    p = ibits(x*iand(y, mask16) + ishft(iand(x*ishft(y, -16), mask16), 16), 0, 32)
  end function mullo32

  !> The SplitMix64 output function (a bijective 64-bit mixer).
  elemental function splitmix64_mix(z0) result(z)
    integer(int64), intent(in) :: z0  !! word to mix [-]
    integer(int64) :: z               !! mixed word [-]
    z = mul64(ieor(z0, ishft(z0, -30)), mul1)
    z = mul64(ieor(z, ishft(z, -27)), mul2)
    z = ieor(z, ishft(z, -31))
  end function splitmix64_mix

  !> One step of the sequential SplitMix64 generator: advances `state`, returns the output.
  function splitmix64_next(state) result(z)
    integer(int64), intent(inout) :: state  !! generator state [-]
    integer(int64) :: z                     !! next 64-bit output [-]
    state = add64(state, gamma64)
    z = splitmix64_mix(state)
  end function splitmix64_next

  !> The 64-bit key of draw `draw` of parameter `param` in case `case_id` (module header).
  elemental function case_key(seed, case_id, param, draw) result(h)
    integer(int64), intent(in) :: seed     !! campaign seed [-]
    integer, intent(in) :: case_id         !! case id, 1.. [-]
    integer, intent(in) :: param           !! parameter index, 1.. [-]
    integer, intent(in) :: draw            !! draw counter, 0.. [-]
    integer(int64) :: h                    !! random 64-bit word [-]
    h = splitmix64_mix(add64(seed, gamma64))
    h = splitmix64_mix(add64(ieor(h, int(case_id, int64)), gamma64))
    h = splitmix64_mix(add64(ieor(h, int(param, int64)), gamma64))
    h = splitmix64_mix(add64(ieor(h, int(draw, int64)), gamma64))
  end function case_key

  !> Uniform deviate in [0, 1) with 53 random bits.
  elemental function case_uniform(seed, case_id, param, draw) result(u)
    integer(int64), intent(in) :: seed     !! campaign seed [-]
    integer, intent(in) :: case_id         !! case id [-]
    integer, intent(in) :: param           !! parameter index [-]
    integer, intent(in) :: draw            !! draw counter [-]
    real(wp) :: u                          !! deviate in [0, 1) [-]
    u = real(ishft(case_key(seed, case_id, param, draw), -11), wp)*2.0_wp**(-53)
  end function case_uniform

  !> Standard normal deviate number `pair` (Box-Muller from draws 2*pair and 2*pair+1).
  elemental function case_normal(seed, case_id, param, pair) result(z)
    integer(int64), intent(in) :: seed     !! campaign seed [-]
    integer, intent(in) :: case_id         !! case id [-]
    integer, intent(in) :: param           !! parameter index [-]
    integer, intent(in) :: pair            !! pair counter, 0.. [-]
    real(wp) :: z                          !! N(0, 1) deviate [-]
    real(wp) :: u1, u2
    u1 = 1.0_wp - case_uniform(seed, case_id, param, 2*pair)      ! (0, 1]
    u2 = case_uniform(seed, case_id, param, 2*pair + 1)
    z = sqrt(-2.0_wp*log(u1))*cos(2.0_wp*pi*u2)
  end function case_normal

  !> Normal deviate with mean `mean` and deviation `sd`, truncated to [lo, hi] by rejection
  !! (draw pairs 0, 1, 2, ... until one falls inside). stat = 1 when `max_tries` pairs fail.
  subroutine case_truncated_normal(seed, case_id, param, mean, sd, lo, hi, max_tries, x, stat)
    integer(int64), intent(in) :: seed     !! campaign seed [-]
    integer, intent(in) :: case_id         !! case id [-]
    integer, intent(in) :: param           !! parameter index [-]
    real(wp), intent(in) :: mean           !! mean [deck unit]
    real(wp), intent(in) :: sd             !! standard deviation, > 0 [deck unit]
    real(wp), intent(in) :: lo, hi         !! truncation bounds, lo < hi (use +-huge for none) [deck unit]
    integer, intent(in) :: max_tries       !! largest number of pairs drawn [-]
    real(wp), intent(out) :: x             !! the deviate [deck unit]
    integer, intent(out) :: stat           !! 0 ok, 1 no draw fell inside [lo, hi] [-]
    integer :: k
    stat = STAT_OK
    do k = 0, max_tries - 1
      x = mean + sd*case_normal(seed, case_id, param, k)
      if (x >= lo .and. x <= hi) return
    end do
    x = mean
    stat = STAT_FAILED
  end subroutine case_truncated_normal

end module landyn_campaign_rng
