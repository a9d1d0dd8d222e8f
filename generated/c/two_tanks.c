/* The `two_tanks` observers in C99, emitted by `mho gen`. Do not edit: regenerate.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include "two_tanks.h"

/* The Rust observer's bits need every float operation rounded on its own: no fused multiply-add
 * (gcc: -ffp-contract=off, the default of its ISO modes such as -std=c99; other compilers follow
 * the standard pragma below), no -ffast-math, and float evaluated as float: FLT_EVAL_METHOD 0,
 * or 16 or 32 (ISO/IEC TS 18661-3: types narrower than _Float16, or _Float32, are evaluated in
 * it, so float stays float; gcc says 16 for a Cortex-M55 or with AVX512-FP16 in its GNU modes). */
#if !defined(__GNUC__) || defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
#if defined(FLT_EVAL_METHOD)
#if FLT_EVAL_METHOD == 1
#error "float expressions are evaluated in double here (FLT_EVAL_METHOD 1): the observers need them evaluated in float"
#elif FLT_EVAL_METHOD == 2
#error "float expressions are evaluated in long double here (FLT_EVAL_METHOD 2, e.g. the x87): use SSE (gcc: -mfpmath=sse)"
#elif FLT_EVAL_METHOD == -1
#error "the format float expressions are evaluated in is indeterminate here (FLT_EVAL_METHOD -1): the observers need float"
#elif FLT_EVAL_METHOD != 0 && FLT_EVAL_METHOD != 16 && FLT_EVAL_METHOD != 32
#error "float expressions are evaluated in a format wider than float here (FLT_EVAL_METHOD not 0, 16 or 32)"
#endif
#endif


/* The bits of v (memcpy: no aliasing, no conversion). */
static uint32_t bits_of(float v) {
    uint32_t x;
    memcpy(&x, &v, sizeof x);
    return x;
}

/* 1 when v is finite: its exponent is not all ones (an integer test, as Rust's is_finite). */
static int is_finite(float v) {
    return (bits_of(v) & 0x7fffffffu) < 0x7f800000u;
}

/* 1 when every output and input of a sample is finite (u is not read without inputs). */
static int accepts(const float *y, const float *u) {
    unsigned i;
    int finite = 1;
    for (i = 0u; i < TWO_TANKS_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    for (i = 0u; i < TWO_TANKS_INPUTS; ++i) {
        finite &= is_finite(u[i]);
    }
    return finite;
}

/* c ? a : b, one select per statement: compilers make it a conditional move (an IT block on
 * Thumb-2), where a chain of them on one condition may become a branch. */
static float choose_float(int c, float a, float b) {
    return c ? a : b;
}

/* c ? a : b by masks, without a branch (c is 0 or 1): the same instructions whatever c is. */
static uint32_t select_bits(int c, uint32_t a, uint32_t b) {
    const uint32_t mask = 0u - (uint32_t)c;
    return (a & mask) | (b & ~mask);
}

static float select_float(int c, float a, float b) {
    uint32_t x = select_bits(c, bits_of(a), bits_of(b));
    memcpy(&a, &x, sizeof a);
    return a;
}


/* target `h1`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_0[20] = {
    5.676462f, 4.547314f, 3.353178f, 2.1643755f,
    1.0956115f, -0.026377345f, -1.05504f, -2.0768101f,
    -3.1210372f, -4.1597195f, -0.045999352f, 1.8826351f,
    1.5663508f, 1.2864056f, 0.9817473f, 0.7472627f,
    0.45704025f, 0.25319105f, 0.12341577f, 0.017332124f
};
static const float SEGMENTS_0[194][2] = {
    { 4.3011494f, 0.12226174f },
    { 4.3022904f, 0.121120736f },
    { 4.3146825f, 0.11492488f },
    { 4.3320236f, 0.10914448f },
    { 4.3501935f, 0.10460195f },
    { 4.3675017f, 0.10114034f },
    { 4.3833265f, 0.098502874f },
    { 4.397477f, 0.09648137f },
    { 4.409935f, 0.09492413f },
    { 4.4207497f, 0.093722455f },
    { 4.429996f, 0.09279782f },
    { 4.4377537f, 0.09209261f },
    { 4.4440994f, 0.09156378f },
    { 4.449106f, 0.09117865f },
    { 4.4528394f, 0.090911984f },
    { 4.4553595f, 0.09074399f },
    { 4.45672f, 0.09065897f },
    { 4.4569693f, 0.090644285f },
    { 4.456153f, 0.090689644f },
    { 4.4543104f, 0.09078662f },
    { 4.451479f, 0.0909282f },
    { 4.4476924f, 0.091108516f },
    { 4.4429817f, 0.09132262f },
    { 4.437377f, 0.091566324f },
    { 4.430904f, 0.09183602f },
    { 4.423589f, 0.09212861f },
    { 4.415456f, 0.09244143f },
    { 4.406527f, 0.092772126f },
    { 4.396824f, 0.09311866f },
    { 4.386368f, 0.09347923f },
    { 4.3751774f, 0.093852244f },
    { 4.363272f, 0.09423628f },
    { 4.3506703f, 0.09463008f },
    { 4.3373904f, 0.09503251f },
    { 4.3234487f, 0.095442556f },
    { 4.3088627f, 0.0958593f },
    { 4.293649f, 0.0962819f },
    { 4.277824f, 0.09670961f },
    { 4.2614036f, 0.09714172f },
    { 4.244404f, 0.09757762f },
    { 4.22684f, 0.09801671f },
    { 4.2087283f, 0.09845846f },
    { 4.1900835f, 0.09890238f },
    { 4.170922f, 0.099348f },
    { 4.151258f, 0.09979491f },
    { 4.131108f, 0.1002427f },
    { 4.110486f, 0.10069099f },
    { 4.0894084f, 0.10113945f },
    { 4.06789f, 0.10158774f },
    { 4.0459466f, 0.10203557f },
    { 4.0235934f, 0.10248263f },
    { 4.000846f, 0.10292867f },
    { 3.9777195f, 0.10337341f },
    { 3.9542298f, 0.103816606f },
    { 3.9303927f, 0.10425804f },
    { 3.9062238f, 0.10469747f },
    { 3.881739f, 0.1051347f },
    { 3.8569539f, 0.10556953f },
    { 3.8318849f, 0.10600175f },
    { 3.8065479f, 0.10643119f },
    { 3.7809591f, 0.10685767f },
    { 3.755135f, 0.107281014f },
    { 3.7290916f, 0.10770107f },
    { 3.7028458f, 0.10811767f },
    { 3.6764138f, 0.10853067f },
    { 3.6498125f, 0.10893992f },
    { 3.6230583f, 0.10934529f },
    { 3.596168f, 0.109746635f },
    { 3.5691588f, 0.110143825f },
    { 3.5420475f, 0.11053675f },
    { 3.514851f, 0.110925265f },
    { 3.4875867f, 0.111309275f },
    { 3.4602714f, 0.11168865f },
    { 3.4329221f, 0.1120633f },
    { 3.4055564f, 0.112433106f },
    { 3.3781917f, 0.11279797f },
    { 3.3508449f, 0.113157794f },
    { 3.3235338f, 0.113512486f },
    { 3.2962751f, 0.113861956f },
    { 3.2690868f, 0.11420611f },
    { 3.241986f, 0.11454487f },
    { 3.2149901f, 0.114878155f },
    { 3.1881166f, 0.115205884f },
    { 3.1613824f, 0.11552798f },
    { 3.1348054f, 0.11584438f },
    { 3.1084025f, 0.116155f },
    { 3.082191f, 0.11645978f },
    { 3.056188f, 0.11675866f },
    { 3.030411f, 0.11705159f },
    { 3.0048766f, 0.117338486f },
    { 2.9796019f, 0.11761932f },
    { 2.954604f, 0.11789402f },
    { 2.929899f, 0.11816255f },
    { 2.905504f, 0.11842486f },
    { 2.8814352f, 0.11868092f },
    { 2.8577092f, 0.11893066f },
    { 2.834342f, 0.11917407f },
    { 2.8113496f, 0.11941111f },
    { 2.7887478f, 0.119641736f },
    { 2.766552f, 0.11986594f },
    { 2.7447777f, 0.12008368f },
    { 2.7234402f, 0.12029494f },
    { 2.7025542f, 0.12049971f },
    { 2.6821342f, 0.12069796f },
    { 2.6621945f, 0.120889686f },
    { 2.6427493f, 0.12107488f },
    { 2.623812f, 0.121253535f },
    { 2.605396f, 0.12142564f },
    { 2.5875144f, 0.12159122f },
    { 2.5701795f, 0.12175025f },
    { 2.5534031f, 0.121902764f },
    { 2.5371976f, 0.12204876f },
    { 2.5215735f, 0.12218826f },
    { 2.5065417f, 0.122321285f },
    { 2.4921124f, 0.122447856f },
    { 2.478295f, 0.12256801f },
    { 2.4650989f, 0.12268177f },
    { 2.4525318f, 0.12278918f },
    { 2.4406016f, 0.122890286f },
    { 2.4293156f, 0.122985125f },
    { 2.4186795f, 0.12307376f },
    { 2.4086988f, 0.12315624f },
    { 2.3993783f, 0.12323264f },
    { 2.3907216f, 0.12330302f },
    { 2.3827314f, 0.12336746f },
    { 2.3754096f, 0.123426035f },
    { 2.3687568f, 0.12347883f },
    { 2.3627725f, 0.123525955f },
    { 2.357455f, 0.12356749f },
    { 2.352802f, 0.12360357f },
    { 2.3488092f, 0.12363428f },
    { 2.345471f, 0.12365976f },
    { 2.34278f, 0.123680145f },
    { 2.3407288f, 0.123695575f },
    { 2.339306f, 0.123706184f },
    { 2.3385005f, 0.12371215f },
    { 2.3382983f, 0.12371364f },
    { 2.3386838f, 0.123710826f },
    { 2.339639f, 0.123703904f },
    { 2.341144f, 0.12369308f },
    { 2.3431768f, 0.12367856f },
    { 2.3457124f, 0.12366058f },
    { 2.3487236f, 0.12363937f },
    { 2.3521805f, 0.1236152f },
    { 2.3560498f, 0.12358832f },
    { 2.3602958f, 0.12355904f },
    { 2.3648791f, 0.12352765f },
    { 2.3697572f, 0.12349447f },
    { 2.374884f, 0.12345983f },
    { 2.380209f, 0.12342409f },
    { 2.3856785f, 0.12338763f },
    { 2.3912349f, 0.12335083f },
    { 2.3968153f, 0.12331411f },
    { 2.4023533f, 0.12327792f },
    { 2.4077773f, 0.1232427f },
    { 2.4130116f, 0.123208925f },
    { 2.4179754f, 0.12317711f },
    { 2.4225836f, 0.123147756f },
    { 2.4267464f, 0.12312141f },
    { 2.4303696f, 0.12309862f },
    { 2.4333556f, 0.12307996f },
    { 2.4356036f, 0.12306599f },
    { 2.4370108f, 0.12305731f },
    { 2.4374733f, 0.123054475f },
    { 2.4368894f, 0.123058036f },
    { 2.4351609f, 0.12306851f },
    { 2.4321976f, 0.12308636f },
    { 2.4279225f, 0.12311196f },
    { 2.422278f, 0.12314556f },
    { 2.4152353f, 0.12318723f },
    { 2.406807f, 0.12323681f },
    { 2.397062f, 0.123293795f },
    { 2.3861494f, 0.123357244f },
    { 2.3743246f, 0.123425595f },
    { 2.36199f, 0.12349648f },
    { 2.349746f, 0.12356645f },
    { 2.338459f, 0.12363058f },
    { 2.3293536f, 0.12368202f },
    { 2.3241334f, 0.12371135f },
    { 2.3251417f, 0.123705715f },
    { 2.3355703f, 0.12364778f },
    { 2.359731f, 0.123514295f },
    { 2.4033957f, 0.12327438f },
    { 2.474213f, 0.1228874f },
    { 2.5821834f, 0.1223006f },
    { 2.7401502f, 0.12144673f },
    { 2.9641929f, 0.1202422f },
    { 3.2737176f, 0.11858699f },
    { 3.6909108f, 0.11636788f },
    { 4.239108f, 0.11346736f },
    { 4.939665f, 0.109780215f },
    { 5.80725f, 0.10523789f },
    { 6.844304f, 0.099836566f },
    { 8.036455f, 0.09365962f }
};

/* target `h2`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[20] = {
    2.4817736f, 2.227527f, 1.8953944f, 1.5256011f,
    1.1762369f, 0.77073723f, 0.3714361f, -0.06182462f,
    -0.5139937f, -1.0251921f, -0.03327894f, 0.060879707f,
    0.12139054f, 0.15905221f, 0.15314394f, 0.15071552f,
    0.103293575f, 0.06578464f, 0.049075376f, 0.0613315f
};
static const float SEGMENTS_1[186][2] = {
    { 4.715646f, 0.088126f },
    { 4.7043943f, 0.099377856f },
    { 4.6918406f, 0.10565465f },
    { 4.683287f, 0.10850574f },
    { 4.679241f, 0.109517224f },
    { 4.6784964f, 0.109666236f },
    { 4.679773f, 0.10945348f },
    { 4.68213f, 0.10911673f },
    { 4.684953f, 0.10876386f },
    { 4.687861f, 0.108440734f },
    { 4.690627f, 0.10816415f },
    { 4.6931214f, 0.1079374f },
    { 4.695276f, 0.10775787f },
    { 4.6970606f, 0.10762057f },
    { 4.69847f, 0.10751989f },
    { 4.699513f, 0.10745036f },
    { 4.7002068f, 0.10740701f },
    { 4.700573f, 0.10738545f },
    { 4.7006373f, 0.10738188f },
    { 4.7004247f, 0.10739308f },
    { 4.69996f, 0.107416295f },
    { 4.6992693f, 0.10744921f },
    { 4.6983743f, 0.107489884f },
    { 4.6972976f, 0.10753669f },
    { 4.69606f, 0.10758825f },
    { 4.694681f, 0.10764342f },
    { 4.693177f, 0.10770125f },
    { 4.6915655f, 0.10776095f },
    { 4.6898603f, 0.107821845f },
    { 4.6880755f, 0.1078834f },
    { 4.686223f, 0.107945144f },
    { 4.6843143f, 0.108006716f },
    { 4.682359f, 0.1080678f },
    { 4.6803675f, 0.10812816f },
    { 4.6783476f, 0.108187586f },
    { 4.6763062f, 0.10824591f },
    { 4.6742506f, 0.10830301f },
    { 4.672187f, 0.108358786f },
    { 4.6701202f, 0.10841317f },
    { 4.668056f, 0.108466096f },
    { 4.6659985f, 0.108517535f },
    { 4.6639514f, 0.10856746f },
    { 4.6619186f, 0.10861586f },
    { 4.6599026f, 0.10866274f },
    { 4.657907f, 0.1087081f },
    { 4.6559334f, 0.10875195f },
    { 4.6539845f, 0.10879432f },
    { 4.6520624f, 0.10883522f },
    { 4.6501675f, 0.10887469f },
    { 4.6483026f, 0.10891276f },
    { 4.646468f, 0.108949445f },
    { 4.6446652f, 0.10898479f },
    { 4.642895f, 0.10901883f },
    { 4.641158f, 0.10905161f },
    { 4.639455f, 0.109083146f },
    { 4.6377864f, 0.10911349f },
    { 4.636152f, 0.109142676f },
    { 4.634553f, 0.10917073f },
    { 4.6329885f, 0.1091977f },
    { 4.6314597f, 0.10922361f },
    { 4.6299663f, 0.109248504f },
    { 4.6285076f, 0.10927241f },
    { 4.6270843f, 0.109295376f },
    { 4.6256957f, 0.109317414f },
    { 4.624342f, 0.10933857f },
    { 4.6230226f, 0.10935886f },
    { 4.621738f, 0.10937833f },
    { 4.6204867f, 0.109397f },
    { 4.6192694f, 0.109414905f },
    { 4.6180854f, 0.109432064f },
    { 4.6169343f, 0.10944851f },
    { 4.6158156f, 0.109464265f },
    { 4.614729f, 0.10947936f },
    { 4.613674f, 0.10949381f },
    { 4.6126504f, 0.109507635f },
    { 4.6116576f, 0.109520875f },
    { 4.6106954f, 0.10953353f },
    { 4.609763f, 0.10954565f },
    { 4.6088605f, 0.10955722f },
    { 4.6079865f, 0.10956828f },
    { 4.607141f, 0.10957885f },
    { 4.606324f, 0.109588936f },
    { 4.6055346f, 0.10959856f },
    { 4.6047726f, 0.10960775f },
    { 4.604037f, 0.1096165f },
    { 4.6033278f, 0.10962485f },
    { 4.6026444f, 0.10963279f },
    { 4.6019864f, 0.10964035f },
    { 4.601353f, 0.10964755f },
    { 4.6007447f, 0.10965438f },
    { 4.60016f, 0.10966088f },
    { 4.5995994f, 0.10966704f },
    { 4.599062f, 0.10967289f },
    { 4.598547f, 0.109678425f },
    { 4.5980544f, 0.10968366f },
    { 4.597584f, 0.10968862f },
    { 4.5971346f, 0.109693296f },
    { 4.5967064f, 0.10969771f },
    { 4.596299f, 0.109701864f },
    { 4.595912f, 0.109705776f },
    { 4.595545f, 0.10970945f },
    { 4.595197f, 0.10971289f },
    { 4.5948687f, 0.10971611f },
    { 4.5945587f, 0.10971912f },
    { 4.594267f, 0.10972192f },
    { 4.593993f, 0.10972453f },
    { 4.593737f, 0.10972695f },
    { 4.593498f, 0.10972918f },
    { 4.5932765f, 0.109731235f },
    { 4.5930705f, 0.10973313f },
    { 4.5928807f, 0.10973485f },
    { 4.5927067f, 0.10973641f },
    { 4.5925484f, 0.109737836f },
    { 4.5924044f, 0.1097391f },
    { 4.592275f, 0.10974024f },
    { 4.5921597f, 0.10974124f },
    { 4.592058f, 0.10974212f },
    { 4.5919704f, 0.10974287f },
    { 4.591895f, 0.109743506f },
    { 4.5918326f, 0.109744035f },
    { 4.591782f, 0.10974445f },
    { 4.5917435f, 0.10974477f },
    { 4.591716f, 0.109744996f },
    { 4.591699f, 0.10974513f },
    { 4.591693f, 0.10974518f },
    { 4.5916967f, 0.10974515f },
    { 4.59171f, 0.10974505f },
    { 4.591732f, 0.10974488f },
    { 4.591763f, 0.10974463f },
    { 4.5918016f, 0.10974433f },
    { 4.5918474f, 0.10974398f },
    { 4.5919003f, 0.10974357f },
    { 4.5919595f, 0.109743126f },
    { 4.592025f, 0.10974264f },
    { 4.5920944f, 0.10974212f },
    { 4.592169f, 0.10974157f },
    { 4.592247f, 0.109740995f },
    { 4.5923276f, 0.10974041f },
    { 4.592411f, 0.1097398f },
    { 4.592496f, 0.10973919f },
    { 4.5925813f, 0.10973858f },
    { 4.592666f, 0.10973798f },
    { 4.59275f, 0.10973739f },
    { 4.592832f, 0.109736815f },
    { 4.5929112f, 0.109736264f },
    { 4.592986f, 0.10973575f },
    { 4.593056f, 0.109735265f },
    { 4.59312f, 0.10973483f },
    { 4.5931764f, 0.10973445f },
    { 4.593225f, 0.109734125f },
    { 4.5932636f, 0.109733865f },
    { 4.5932918f, 0.109733686f },
    { 4.593308f, 0.109733574f },
    { 4.593311f, 0.10973355f },
    { 4.5933003f, 0.109733626f },
    { 4.593274f, 0.10973379f },
    { 4.593232f, 0.10973406f },
    { 4.5931735f, 0.10973444f },
    { 4.5930977f, 0.109734915f },
    { 4.593004f, 0.109735504f },
    { 4.5928936f, 0.1097362f },
    { 4.5927663f, 0.10973699f },
    { 4.592624f, 0.109737866f },
    { 4.592469f, 0.10973881f },
    { 4.592305f, 0.10973982f },
    { 4.5921373f, 0.10974083f },
    { 4.591973f, 0.10974182f },
    { 4.591822f, 0.10974272f },
    { 4.5916986f, 0.10974346f },
    { 4.5916204f, 0.10974392f },
    { 4.591612f, 0.109743975f },
    { 4.5917053f, 0.109743424f },
    { 4.5919433f, 0.109742045f },
    { 4.592383f, 0.109739505f },
    { 4.5931f, 0.109735385f },
    { 4.594196f, 0.10972912f },
    { 4.5958066f, 0.10971996f },
    { 4.598117f, 0.109706916f },
    { 4.601378f, 0.109688595f },
    { 4.605935f, 0.10966314f },
    { 4.6122713f, 0.10962793f },
    { 4.621066f, 0.10957934f },
    { 4.6332955f, 0.10951215f },
    { 4.6503844f, 0.109418765f },
    { 4.6744585f, 0.10928793f },
    { 4.7087693f, 0.109102465f }
};

/* floor(t) for 0 <= t, at most count - 1: a uniform table's segment. Any other t (negative, NaN,
 * infinite) gives some segment, whose value evaluate replaces by r_min or r_max. The clamp is an
 * unsigned minimum of the bits of |t|, which are ordered as the values: the conversion is always
 * defined, and the same instructions run whatever t is. */
static uint32_t uniform_segment(float t, uint32_t count) {
    const uint32_t magnitude = bits_of(t) & 0x7fffffffu;
    const uint32_t last = bits_of((float)(count - 1u));
    const uint32_t least = magnitude < last ? magnitude : last;
    float clamped;
    memcpy(&clamped, &least, sizeof clamped);
    return (uint32_t)clamped;
}

/* r(t) on one segment (a, b) starting at `start`, held at r_min below 0 (or NaN) and r_max above
 * t_max (t_max >= 0: never both); as firmware::InverseTable, by one select per statement, which
 * compilers make a conditional move (an IT block on Thumb-2): the same instructions whatever t is. */
static void evaluate(float t, const float *segment, float start, float t_max, float r_min, float r_max,
                     float *value, two_tanks_saturation *saturation) {
    const int low = !(t >= 0.0f);
    const int high = t > t_max;
    float r = segment[0] + segment[1] * (t - start);
    r = choose_float(high, r_max, r);
    r = choose_float(low, r_min, r);
    *value = r;
    *saturation = (two_tanks_saturation)((unsigned)low | (unsigned)high << 1);
}

void two_tanks_map_init(two_tanks_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

two_tanks_status two_tanks_map_push(two_tanks_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < TWO_TANKS_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    for (i = 0u; i < TWO_TANKS_INPUTS; ++i) {
        finite &= is_finite(u[i]);
    }
    if (!finite) {
        return TWO_TANKS_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < TWO_TANKS_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + TWO_TANKS_HORIZON][i] = y[i];
    }
    for (i = 0u; i < TWO_TANKS_INPUTS; ++i) {
        observer->u[slot][i] = u[i];
        observer->u[slot + TWO_TANKS_HORIZON][i] = u[i];
    }
    observer->next = slot + 1u >= TWO_TANKS_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < TWO_TANKS_HORIZON);
    return TWO_TANKS_OK;
}

two_tanks_status two_tanks_map_estimate(const two_tanks_map *observer, float *values, two_tanks_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < TWO_TANKS_HORIZON) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    const float t_0 = -60.96606f
        + GAINS_0[0] * observer->y[next + 9u][0]
        + GAINS_0[1] * observer->y[next + 8u][0]
        + GAINS_0[2] * observer->y[next + 7u][0]
        + GAINS_0[3] * observer->y[next + 6u][0]
        + GAINS_0[4] * observer->y[next + 5u][0]
        + GAINS_0[5] * observer->y[next + 4u][0]
        + GAINS_0[6] * observer->y[next + 3u][0]
        + GAINS_0[7] * observer->y[next + 2u][0]
        + GAINS_0[8] * observer->y[next + 1u][0]
        + GAINS_0[9] * observer->y[next + 0u][0]
        + GAINS_0[10] * observer->u[next + 9u][0]
        + GAINS_0[11] * observer->u[next + 8u][0]
        + GAINS_0[12] * observer->u[next + 7u][0]
        + GAINS_0[13] * observer->u[next + 6u][0]
        + GAINS_0[14] * observer->u[next + 5u][0]
        + GAINS_0[15] * observer->u[next + 4u][0]
        + GAINS_0[16] * observer->u[next + 3u][0]
        + GAINS_0[17] * observer->u[next + 2u][0]
        + GAINS_0[18] * observer->u[next + 1u][0]
        + GAINS_0[19] * observer->u[next + 0u][0];
    const float t_1 = -46.135227f
        + GAINS_1[0] * observer->y[next + 9u][0]
        + GAINS_1[1] * observer->y[next + 8u][0]
        + GAINS_1[2] * observer->y[next + 7u][0]
        + GAINS_1[3] * observer->y[next + 6u][0]
        + GAINS_1[4] * observer->y[next + 5u][0]
        + GAINS_1[5] * observer->y[next + 4u][0]
        + GAINS_1[6] * observer->y[next + 3u][0]
        + GAINS_1[7] * observer->y[next + 2u][0]
        + GAINS_1[8] * observer->y[next + 1u][0]
        + GAINS_1[9] * observer->y[next + 0u][0]
        + GAINS_1[10] * observer->u[next + 9u][0]
        + GAINS_1[11] * observer->u[next + 8u][0]
        + GAINS_1[12] * observer->u[next + 7u][0]
        + GAINS_1[13] * observer->u[next + 6u][0]
        + GAINS_1[14] * observer->u[next + 5u][0]
        + GAINS_1[15] * observer->u[next + 4u][0]
        + GAINS_1[16] * observer->u[next + 3u][0]
        + GAINS_1[17] * observer->u[next + 2u][0]
        + GAINS_1[18] * observer->u[next + 1u][0]
        + GAINS_1[19] * observer->u[next + 0u][0];
    const uint32_t k_0 = uniform_segment(t_0, 194u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 194.0f, 4.3011494f, 26.20642f, &values[0], &saturation[0]);
    const uint32_t k_1 = uniform_segment(t_1, 186u);
    evaluate(t_1, SEGMENTS_1[k_1], 0.0f, 186.0f, 4.715646f, 25.001827f, &values[1], &saturation[1]);
    return TWO_TANKS_OK;
}


#define TWO_TANKS_MAP_ROWS TWO_TANKS_TARGETS
#define start_map_estimate two_tanks_map_estimate

/* `h1` in integers: gains in regressor order (2^-19 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_0[20] = { 5813, 4656, 3434, 2216, 1122, -27, -1080, -2127, -3196, -4260, -24, 964, 802, 659, 503, 383, 234, 130, 63, 9 };
static const int32_t FIXED_SEGMENTS_0[194][2] = {
    { 2255041, 64100 },
    { 2319141, 63502 },
    { 2382644, 60254 },
    { 2442897, 57223 },
    { 2500120, 54842 },
    { 2554962, 53027 },
    { 2607989, 51644 },
    { 2659633, 50584 },
    { 2710217, 49768 },
    { 2759984, 49138 },
    { 2809122, 48653 },
    { 2857775, 48283 },
    { 2906058, 48006 },
    { 2954063, 47804 },
    { 3001867, 47664 },
    { 3049531, 47576 },
    { 3097107, 47531 },
    { 3144639, 47524 },
    { 3192162, 47547 },
    { 3239710, 47598 },
    { 3287308, 47673 },
    { 3334981, 47767 },
    { 3382748, 47879 },
    { 3430627, 48007 },
    { 3478634, 48149 },
    { 3526783, 48302 },
    { 3575085, 48466 },
    { 3623551, 48639 },
    { 3672190, 48821 },
    { 3721011, 49010 },
    { 3770021, 49206 },
    { 3819227, 49407 },
    { 3868634, 49613 },
    { 3918247, 49824 },
    { 3968071, 50039 },
    { 4018111, 50258 },
    { 4068369, 50479 },
    { 4118848, 50704 },
    { 4169552, 50930 },
    { 4220482, 51159 },
    { 4271641, 51389 },
    { 4323030, 51621 },
    { 4374650, 51853 },
    { 4426504, 52087 },
    { 4478591, 52321 },
    { 4530912, 52556 },
    { 4583468, 52791 },
    { 4636259, 53026 },
    { 4689285, 53261 },
    { 4742547, 53496 },
    { 4796043, 53730 },
    { 4849773, 53964 },
    { 4903737, 54197 },
    { 4957935, 54430 },
    { 5012365, 54661 },
    { 5067026, 54892 },
    { 5121917, 55121 },
    { 5177038, 55349 },
    { 5232387, 55575 },
    { 5287963, 55801 },
    { 5343763, 56024 },
    { 5399787, 56246 },
    { 5456033, 56466 },
    { 5512500, 56685 },
    { 5569185, 56901 },
    { 5626086, 57116 },
    { 5683202, 57328 },
    { 5740530, 57539 },
    { 5798069, 57747 },
    { 5855816, 57953 },
    { 5913769, 58157 },
    { 5971926, 58358 },
    { 6030284, 58557 },
    { 6088841, 58753 },
    { 6147595, 58947 },
    { 6206542, 59139 },
    { 6265681, 59327 },
    { 6325008, 59513 },
    { 6384521, 59696 },
    { 6444218, 59877 },
    { 6504094, 60055 },
    { 6564149, 60229 },
    { 6624378, 60401 },
    { 6684779, 60570 },
    { 6745349, 60736 },
    { 6806085, 60899 },
    { 6866984, 61058 },
    { 6928042, 61215 },
    { 6989257, 61369 },
    { 7050626, 61519 },
    { 7112145, 61666 },
    { 7173812, 61810 },
    { 7235622, 61951 },
    { 7297573, 62089 },
    { 7359662, 62223 },
    { 7421885, 62354 },
    { 7484239, 62482 },
    { 7546720, 62606 },
    { 7609326, 62727 },
    { 7672053, 62844 },
    { 7734897, 62958 },
    { 7797856, 63069 },
    { 7860925, 63177 },
    { 7924101, 63280 },
    { 7987382, 63381 },
    { 8050763, 63478 },
    { 8114241, 63572 },
    { 8177813, 63662 },
    { 8241475, 63749 },
    { 8305224, 63832 },
    { 8369056, 63912 },
    { 8432968, 63989 },
    { 8496957, 64062 },
    { 8561019, 64132 },
    { 8625150, 64198 },
    { 8689348, 64261 },
    { 8753609, 64321 },
    { 8817930, 64377 },
    { 8882306, 64430 },
    { 8946736, 64480 },
    { 9011216, 64526 },
    { 9075742, 64569 },
    { 9140311, 64609 },
    { 9204921, 64646 },
    { 9269567, 64680 },
    { 9334247, 64711 },
    { 9398958, 64738 },
    { 9463696, 64763 },
    { 9528460, 64785 },
    { 9593245, 64804 },
    { 9658048, 64820 },
    { 9722868, 64833 },
    { 9787702, 64844 },
    { 9852546, 64852 },
    { 9917398, 64858 },
    { 9982256, 64861 },
    { 10047116, 64862 },
    { 10111978, 64860 },
    { 10176838, 64856 },
    { 10241694, 64851 },
    { 10306545, 64843 },
    { 10371388, 64834 },
    { 10436222, 64823 },
    { 10501045, 64810 },
    { 10565855, 64796 },
    { 10630651, 64781 },
    { 10695431, 64764 },
    { 10760195, 64747 },
    { 10824942, 64729 },
    { 10889670, 64710 },
    { 10954380, 64691 },
    { 11019071, 64671 },
    { 11083742, 64652 },
    { 11148394, 64633 },
    { 11213027, 64615 },
    { 11277642, 64597 },
    { 11342239, 64580 },
    { 11406819, 64565 },
    { 11471384, 64551 },
    { 11535935, 64539 },
    { 11600474, 64529 },
    { 11665004, 64522 },
    { 11729526, 64517 },
    { 11794043, 64516 },
    { 11858559, 64518 },
    { 11923077, 64523 },
    { 11987601, 64533 },
    { 12052133, 64546 },
    { 12116679, 64564 },
    { 12181243, 64586 },
    { 12245829, 64612 },
    { 12310440, 64641 },
    { 12375082, 64675 },
    { 12439756, 64711 },
    { 12504467, 64748 },
    { 12569215, 64784 },
    { 12633999, 64818 },
    { 12698817, 64845 },
    { 12763662, 64860 },
    { 12828523, 64857 },
    { 12893380, 64827 },
    { 12958207, 64757 },
    { 13022964, 64631 },
    { 13087595, 64428 },
    { 13152024, 64121 },
    { 13216144, 63673 },
    { 13279818, 63042 },
    { 13342859, 62174 },
    { 13405033, 61010 },
    { 13466043, 59490 },
    { 13525533, 57556 },
    { 13583089, 55175 },
    { 13638264, 52343 },
    { 13690607, 49105 }
};

/* `h2` in integers: gains in regressor order (2^-20 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_1[20] = { 5083, 4562, 3882, 3124, 2409, 1578, 761, -127, -1053, -2100, -34, 62, 124, 163, 157, 154, 106, 67, 50, 63 };
static const int32_t FIXED_SEGMENTS_1[186][2] = {
    { 2472357, 46203 },
    { 2518560, 52103 },
    { 2570663, 55393 },
    { 2626056, 56888 },
    { 2682944, 57419 },
    { 2740363, 57497 },
    { 2797860, 57385 },
    { 2855245, 57209 },
    { 2912453, 57024 },
    { 2969477, 56854 },
    { 3026331, 56709 },
    { 3083040, 56590 },
    { 3139631, 56496 },
    { 3196127, 56424 },
    { 3252551, 56371 },
    { 3308922, 56335 },
    { 3365257, 56312 },
    { 3421569, 56301 },
    { 3477870, 56299 },
    { 3534169, 56305 },
    { 3590474, 56317 },
    { 3646791, 56334 },
    { 3703126, 56356 },
    { 3759481, 56380 },
    { 3815862, 56407 },
    { 3872269, 56436 },
    { 3928705, 56466 },
    { 3985171, 56498 },
    { 4041669, 56530 },
    { 4098199, 56562 },
    { 4154761, 56594 },
    { 4211355, 56627 },
    { 4267982, 56659 },
    { 4324640, 56690 },
    { 4381331, 56721 },
    { 4438052, 56752 },
    { 4494804, 56782 },
    { 4551586, 56811 },
    { 4608397, 56840 },
    { 4665237, 56867 },
    { 4722105, 56894 },
    { 4778999, 56921 },
    { 4835920, 56946 },
    { 4892866, 56971 },
    { 4949836, 56994 },
    { 5006831, 57017 },
    { 5063848, 57040 },
    { 5120887, 57061 },
    { 5177948, 57082 },
    { 5235030, 57102 },
    { 5292132, 57121 },
    { 5349253, 57139 },
    { 5406392, 57157 },
    { 5463549, 57174 },
    { 5520724, 57191 },
    { 5577915, 57207 },
    { 5635122, 57222 },
    { 5692344, 57237 },
    { 5749581, 57251 },
    { 5806832, 57265 },
    { 5864096, 57278 },
    { 5921374, 57290 },
    { 5978664, 57302 },
    { 6035967, 57314 },
    { 6093280, 57325 },
    { 6150605, 57336 },
    { 6207941, 57346 },
    { 6265287, 57356 },
    { 6322642, 57365 },
    { 6380007, 57374 },
    { 6437381, 57383 },
    { 6494764, 57391 },
    { 6552154, 57399 },
    { 6609553, 57406 },
    { 6666959, 57414 },
    { 6724373, 57420 },
    { 6781793, 57427 },
    { 6839220, 57433 },
    { 6896654, 57440 },
    { 6954093, 57445 },
    { 7011539, 57451 },
    { 7068990, 57456 },
    { 7126446, 57461 },
    { 7183907, 57466 },
    { 7241373, 57471 },
    { 7298844, 57475 },
    { 7356319, 57479 },
    { 7413798, 57483 },
    { 7471281, 57487 },
    { 7528768, 57490 },
    { 7586258, 57494 },
    { 7643752, 57497 },
    { 7701249, 57500 },
    { 7758750, 57503 },
    { 7816253, 57506 },
    { 7873758, 57508 },
    { 7931267, 57511 },
    { 7988778, 57513 },
    { 8046291, 57515 },
    { 8103806, 57517 },
    { 8161324, 57519 },
    { 8218843, 57521 },
    { 8276364, 57523 },
    { 8333887, 57524 },
    { 8391411, 57526 },
    { 8448937, 57527 },
    { 8506465, 57529 },
    { 8563993, 57530 },
    { 8621523, 57531 },
    { 8679054, 57532 },
    { 8736585, 57533 },
    { 8794118, 57533 },
    { 8851652, 57534 },
    { 8909186, 57535 },
    { 8966721, 57535 },
    { 9024256, 57536 },
    { 9081792, 57536 },
    { 9139329, 57537 },
    { 9196866, 57537 },
    { 9254403, 57537 },
    { 9311940, 57538 },
    { 9369478, 57538 },
    { 9427016, 57538 },
    { 9484554, 57538 },
    { 9542092, 57538 },
    { 9599630, 57538 },
    { 9657168, 57538 },
    { 9714706, 57538 },
    { 9772244, 57538 },
    { 9829782, 57538 },
    { 9887319, 57537 },
    { 9944857, 57537 },
    { 10002394, 57537 },
    { 10059931, 57537 },
    { 10117468, 57536 },
    { 10175004, 57536 },
    { 10232540, 57536 },
    { 10290076, 57536 },
    { 10347612, 57535 },
    { 10405147, 57535 },
    { 10462682, 57535 },
    { 10520217, 57534 },
    { 10577751, 57534 },
    { 10635285, 57534 },
    { 10692819, 57533 },
    { 10750352, 57533 },
    { 10807885, 57533 },
    { 10865418, 57533 },
    { 10922951, 57532 },
    { 10980483, 57532 },
    { 11038016, 57532 },
    { 11095548, 57532 },
    { 11153080, 57532 },
    { 11210612, 57532 },
    { 11268144, 57532 },
    { 11325676, 57532 },
    { 11383208, 57532 },
    { 11440740, 57532 },
    { 11498273, 57533 },
    { 11555805, 57533 },
    { 11613338, 57533 },
    { 11670872, 57534 },
    { 11728405, 57534 },
    { 11785940, 57535 },
    { 11843474, 57535 },
    { 11901010, 57536 },
    { 11958545, 57536 },
    { 12016082, 57537 },
    { 12073619, 57537 },
    { 12131156, 57537 },
    { 12188693, 57537 },
    { 12246231, 57537 },
    { 12303768, 57536 },
    { 12361304, 57535 },
    { 12418839, 57533 },
    { 12476372, 57530 },
    { 12533902, 57525 },
    { 12591427, 57518 },
    { 12648945, 57508 },
    { 12706453, 57495 },
    { 12763948, 57477 },
    { 12821425, 57451 },
    { 12878876, 57416 },
    { 12936292, 57367 },
    { 12993659, 57298 },
    { 13050957, 57201 }
};

/* Signed right shifts must be arithmetic (implementation-defined in C99; so on gcc, clang, armcc
 * and IAR): checked at compile time. */
typedef char fixed_shifts_are_arithmetic[((-8) >> 1) == -4 ? 1 : -1];

/* a - b modulo 2^32 (no signed overflow, which C leaves undefined): t_last - t for any t. */
static int32_t wrapping_sub(int32_t a, int32_t b) {
    return (int32_t)((uint32_t)a - (uint32_t)b);
}

/* min <= v <= max, as one unsigned comparison. */
static int in_range(int32_t v, int32_t min, int32_t max) {
    return (uint32_t)v - (uint32_t)min <= (uint32_t)max - (uint32_t)min;
}

/* firmware::fixed::FixedTable::evaluate: t clamped to the table [0, t_last] by sign masks (no
 * branch: the same instructions whatever t is), then the segment and the position in it by shifts. */
static void fixed_evaluate(int32_t t, const int32_t segments[][2], unsigned f, unsigned dropped, unsigned p,
                           int32_t t_last, int32_t *value, two_tanks_saturation *saturation) {
    const int32_t low = t >> 31;
    const int32_t high = (wrapping_sub(t_last, t) >> 31) & ~low;
    int32_t k;
    int32_t position;
    t &= ~low;
    t ^= (t ^ t_last) & high;
    k = t >> f;
    position = (t - (int32_t)((uint32_t)k << f)) >> dropped;
    *value = segments[k][0] + ((segments[k][1] * position) >> p);
    *saturation = (two_tanks_saturation)((unsigned)(low & 1) | ((unsigned)high & 2u));
}

void two_tanks_fixed_init(two_tanks_fixed *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

two_tanks_status two_tanks_fixed_push(two_tanks_fixed *observer, const int32_t *y, const int32_t *u) {
    unsigned i;
    unsigned slot;
    int inside = 1;
    inside &= in_range(y[0], -32767, 32767);
    inside &= in_range(u[0], -32767, 32767);
    if (!inside) {
        return TWO_TANKS_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < TWO_TANKS_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + TWO_TANKS_HORIZON][i] = y[i];
    }
    for (i = 0u; i < TWO_TANKS_INPUTS; ++i) {
        observer->u[slot][i] = u[i];
        observer->u[slot + TWO_TANKS_HORIZON][i] = u[i];
    }
    observer->next = slot + 1u >= TWO_TANKS_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < TWO_TANKS_HORIZON);
    return TWO_TANKS_OK;
}

/* The sums are in int32_t: every stored sample is in range, where the proof says they fit. */
two_tanks_status two_tanks_fixed_estimate(const two_tanks_fixed *observer, int32_t *values, two_tanks_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < TWO_TANKS_HORIZON) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    int32_t t_0 = -31963774;
    int32_t t_1 = -48376292;
    {
        const int32_t z = observer->y[next + 9u][0];
        t_0 += FIXED_GAINS_0[0] * z;
        t_1 += FIXED_GAINS_1[0] * z;
    }
    {
        const int32_t z = observer->y[next + 8u][0];
        t_0 += FIXED_GAINS_0[1] * z;
        t_1 += FIXED_GAINS_1[1] * z;
    }
    {
        const int32_t z = observer->y[next + 7u][0];
        t_0 += FIXED_GAINS_0[2] * z;
        t_1 += FIXED_GAINS_1[2] * z;
    }
    {
        const int32_t z = observer->y[next + 6u][0];
        t_0 += FIXED_GAINS_0[3] * z;
        t_1 += FIXED_GAINS_1[3] * z;
    }
    {
        const int32_t z = observer->y[next + 5u][0];
        t_0 += FIXED_GAINS_0[4] * z;
        t_1 += FIXED_GAINS_1[4] * z;
    }
    {
        const int32_t z = observer->y[next + 4u][0];
        t_0 += FIXED_GAINS_0[5] * z;
        t_1 += FIXED_GAINS_1[5] * z;
    }
    {
        const int32_t z = observer->y[next + 3u][0];
        t_0 += FIXED_GAINS_0[6] * z;
        t_1 += FIXED_GAINS_1[6] * z;
    }
    {
        const int32_t z = observer->y[next + 2u][0];
        t_0 += FIXED_GAINS_0[7] * z;
        t_1 += FIXED_GAINS_1[7] * z;
    }
    {
        const int32_t z = observer->y[next + 1u][0];
        t_0 += FIXED_GAINS_0[8] * z;
        t_1 += FIXED_GAINS_1[8] * z;
    }
    {
        const int32_t z = observer->y[next + 0u][0];
        t_0 += FIXED_GAINS_0[9] * z;
        t_1 += FIXED_GAINS_1[9] * z;
    }
    {
        const int32_t z = observer->u[next + 9u][0];
        t_0 += FIXED_GAINS_0[10] * z;
        t_1 += FIXED_GAINS_1[10] * z;
    }
    {
        const int32_t z = observer->u[next + 8u][0];
        t_0 += FIXED_GAINS_0[11] * z;
        t_1 += FIXED_GAINS_1[11] * z;
    }
    {
        const int32_t z = observer->u[next + 7u][0];
        t_0 += FIXED_GAINS_0[12] * z;
        t_1 += FIXED_GAINS_1[12] * z;
    }
    {
        const int32_t z = observer->u[next + 6u][0];
        t_0 += FIXED_GAINS_0[13] * z;
        t_1 += FIXED_GAINS_1[13] * z;
    }
    {
        const int32_t z = observer->u[next + 5u][0];
        t_0 += FIXED_GAINS_0[14] * z;
        t_1 += FIXED_GAINS_1[14] * z;
    }
    {
        const int32_t z = observer->u[next + 4u][0];
        t_0 += FIXED_GAINS_0[15] * z;
        t_1 += FIXED_GAINS_1[15] * z;
    }
    {
        const int32_t z = observer->u[next + 3u][0];
        t_0 += FIXED_GAINS_0[16] * z;
        t_1 += FIXED_GAINS_1[16] * z;
    }
    {
        const int32_t z = observer->u[next + 2u][0];
        t_0 += FIXED_GAINS_0[17] * z;
        t_1 += FIXED_GAINS_1[17] * z;
    }
    {
        const int32_t z = observer->u[next + 1u][0];
        t_0 += FIXED_GAINS_0[18] * z;
        t_1 += FIXED_GAINS_1[18] * z;
    }
    {
        const int32_t z = observer->u[next + 0u][0];
        t_0 += FIXED_GAINS_0[19] * z;
        t_1 += FIXED_GAINS_1[19] * z;
    }
    fixed_evaluate(t_0, FIXED_SEGMENTS_0, 19u, 4u, 15u, 101711871, &values[0], &saturation[0]);
    fixed_evaluate(t_1, FIXED_SEGMENTS_1, 20u, 5u, 15u, 195035135, &values[1], &saturation[1]);
    return TWO_TANKS_OK;
}

/* 1 with the sign of v (NaN stays NaN), as firmware::Maths::signum; NaN told by its bits. */
static float signum(float v) {
    return select_float((bits_of(v) & 0x7fffffffu) > 0x7f800000u, v, copysignf(1.0f, v));
}


/* 1 when every input is finite. */
static int inputs_finite(const float *u) {
    unsigned i;
    int finite = 1;
    for (i = 0u; i < TWO_TANKS_INPUTS; ++i) {
        finite &= is_finite(u[i]);
    }
    return finite;
}

/* 1 when the n values from v are finite. */
static int all_finite(const float *v, unsigned n) {
    unsigned i;
    int finite = 1;
    for (i = 0u; i < n; ++i) {
        finite &= is_finite(v[i]);
    }
    return finite;
}

/* The targets at state x and input u. */
static void targets(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    out[0] = t0;
    out[1] = t1;
}

/* One EKF sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's ekf_measured. */
static void ekf_measured(const float *x, const float *p, const float *y, const float *u, float *out) {
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 1.0f;
    const float t6 = 0.04f;
    const float t7 = t6 + t4;
    const float t8 = t5 / t7;
    const float t9 = t3 * t8;
    const float t10 = t4 * t8;
    const float t11 = y[0];
    const float t12 = t11 - t1;
    const float t13 = t9 * t12;
    const float t14 = t0 + t13;
    const float t15 = t10 * t12;
    const float t16 = t1 + t15;
    const float t17 = t12 * t12;
    const float t18 = t17 * t8;
    const float t19 = -t9;
    const float t20 = t5 - t10;
    const float t21 = t19 * t3;
    const float t22 = t2 + t21;
    const float t23 = t19 * t4;
    const float t24 = t3 + t23;
    const float t25 = t20 * t4;
    const float t26 = t24 * t19;
    const float t27 = t22 + t26;
    const float t28 = t24 * t20;
    const float t29 = t25 * t20;
    const float t30 = t9 * t6;
    const float t31 = t30 * t9;
    const float t32 = t27 + t31;
    const float t33 = t30 * t10;
    const float t34 = t28 + t33;
    const float t35 = t10 * t6;
    const float t36 = t35 * t10;
    const float t37 = t29 + t36;
    const float t38 = 2.0f;
    const float t39 = 6.0f;
    const float t40 = t5 / t38;
    const float t41 = t5 / t39;
    const float t42 = 0.178f /* a1 */;
    const float t43 = 981.0f /* g */;
    const float t44 = t38 * t43;
    const float t45 = fabsf(t14);
    const float t46 = t44 * t45;
    const float t47 = sqrtf(t46);
    const float t48 = t42 * t47;
    const float t49 = 0.5f;
    const float t50 = t49 / t47;
    const float t51 = signum(t14);
    const float t52 = t44 * t51;
    const float t53 = t50 * t52;
    const float t54 = t42 * t53;
    const float t55 = 0.178f /* a2 */;
    const float t56 = fabsf(t16);
    const float t57 = t44 * t56;
    const float t58 = sqrtf(t57);
    const float t59 = t55 * t58;
    const float t60 = t49 / t58;
    const float t61 = signum(t16);
    const float t62 = t44 * t61;
    const float t63 = t60 * t62;
    const float t64 = t55 * t63;
    const float t65 = 3.3f /* k */;
    const float t66 = u[0];
    const float t67 = t65 * t66;
    const float t68 = t67 - t48;
    const float t69 = 15.5f /* A1 */;
    const float t70 = t68 / t69;
    const float t71 = -1.0f;
    const float t72 = t71 / t69;
    const float t73 = t72 * t54;
    const float t74 = t48 - t59;
    const float t75 = 15.5f /* A2 */;
    const float t76 = t74 / t75;
    const float t77 = t5 / t75;
    const float t78 = t77 * t54;
    const float t79 = t71 / t75;
    const float t80 = t79 * t64;
    const float t81 = t40 * t70;
    const float t82 = t14 + t81;
    const float t83 = t40 * t76;
    const float t84 = t16 + t83;
    const float t85 = t40 * t73;
    const float t86 = t5 + t85;
    const float t87 = t40 * t78;
    const float t88 = t40 * t80;
    const float t89 = t5 + t88;
    const float t90 = fabsf(t82);
    const float t91 = t44 * t90;
    const float t92 = sqrtf(t91);
    const float t93 = t42 * t92;
    const float t94 = t49 / t92;
    const float t95 = signum(t82);
    const float t96 = t44 * t95;
    const float t97 = t94 * t96;
    const float t98 = t42 * t97;
    const float t99 = fabsf(t84);
    const float t100 = t44 * t99;
    const float t101 = sqrtf(t100);
    const float t102 = t55 * t101;
    const float t103 = t49 / t101;
    const float t104 = signum(t84);
    const float t105 = t44 * t104;
    const float t106 = t103 * t105;
    const float t107 = t55 * t106;
    const float t108 = t67 - t93;
    const float t109 = t108 / t69;
    const float t110 = t72 * t98;
    const float t111 = t93 - t102;
    const float t112 = t111 / t75;
    const float t113 = t77 * t98;
    const float t114 = t79 * t107;
    const float t115 = t110 * t86;
    const float t116 = t113 * t86;
    const float t117 = t114 * t87;
    const float t118 = t116 + t117;
    const float t119 = t114 * t89;
    const float t120 = t40 * t109;
    const float t121 = t14 + t120;
    const float t122 = t40 * t112;
    const float t123 = t16 + t122;
    const float t124 = t40 * t115;
    const float t125 = t5 + t124;
    const float t126 = t40 * t118;
    const float t127 = t40 * t119;
    const float t128 = t5 + t127;
    const float t129 = fabsf(t121);
    const float t130 = t44 * t129;
    const float t131 = sqrtf(t130);
    const float t132 = t42 * t131;
    const float t133 = t49 / t131;
    const float t134 = signum(t121);
    const float t135 = t44 * t134;
    const float t136 = t133 * t135;
    const float t137 = t42 * t136;
    const float t138 = fabsf(t123);
    const float t139 = t44 * t138;
    const float t140 = sqrtf(t139);
    const float t141 = t55 * t140;
    const float t142 = t49 / t140;
    const float t143 = signum(t123);
    const float t144 = t44 * t143;
    const float t145 = t142 * t144;
    const float t146 = t55 * t145;
    const float t147 = t67 - t132;
    const float t148 = t147 / t69;
    const float t149 = t72 * t137;
    const float t150 = t132 - t141;
    const float t151 = t150 / t75;
    const float t152 = t77 * t137;
    const float t153 = t79 * t146;
    const float t154 = t149 * t125;
    const float t155 = t152 * t125;
    const float t156 = t153 * t126;
    const float t157 = t155 + t156;
    const float t158 = t153 * t128;
    const float t159 = t14 + t148;
    const float t160 = t16 + t151;
    const float t161 = t5 + t154;
    const float t162 = t5 + t158;
    const float t163 = fabsf(t159);
    const float t164 = t44 * t163;
    const float t165 = sqrtf(t164);
    const float t166 = t42 * t165;
    const float t167 = t49 / t165;
    const float t168 = signum(t159);
    const float t169 = t44 * t168;
    const float t170 = t167 * t169;
    const float t171 = t42 * t170;
    const float t172 = fabsf(t160);
    const float t173 = t44 * t172;
    const float t174 = sqrtf(t173);
    const float t175 = t55 * t174;
    const float t176 = t49 / t174;
    const float t177 = signum(t160);
    const float t178 = t44 * t177;
    const float t179 = t176 * t178;
    const float t180 = t55 * t179;
    const float t181 = t67 - t166;
    const float t182 = t181 / t69;
    const float t183 = t72 * t171;
    const float t184 = t166 - t175;
    const float t185 = t184 / t75;
    const float t186 = t77 * t171;
    const float t187 = t79 * t180;
    const float t188 = t183 * t161;
    const float t189 = t186 * t161;
    const float t190 = t187 * t157;
    const float t191 = t189 + t190;
    const float t192 = t187 * t162;
    const float t193 = t109 + t148;
    const float t194 = t38 * t193;
    const float t195 = t70 + t194;
    const float t196 = t195 + t182;
    const float t197 = t41 * t196;
    const float t198 = t14 + t197;
    const float t199 = t112 + t151;
    const float t200 = t38 * t199;
    const float t201 = t76 + t200;
    const float t202 = t201 + t185;
    const float t203 = t41 * t202;
    const float t204 = t16 + t203;
    const float t205 = t115 + t154;
    const float t206 = t38 * t205;
    const float t207 = t73 + t206;
    const float t208 = t207 + t188;
    const float t209 = t41 * t208;
    const float t210 = t5 + t209;
    const float t211 = t118 + t157;
    const float t212 = t38 * t211;
    const float t213 = t78 + t212;
    const float t214 = t213 + t191;
    const float t215 = t41 * t214;
    const float t216 = t119 + t158;
    const float t217 = t38 * t216;
    const float t218 = t80 + t217;
    const float t219 = t218 + t192;
    const float t220 = t41 * t219;
    const float t221 = t5 + t220;
    const float t222 = t210 * t32;
    const float t223 = t210 * t34;
    const float t224 = t215 * t32;
    const float t225 = t221 * t34;
    const float t226 = t224 + t225;
    const float t227 = t215 * t34;
    const float t228 = t221 * t37;
    const float t229 = t227 + t228;
    const float t230 = t222 * t210;
    const float t231 = t222 * t215;
    const float t232 = t223 * t221;
    const float t233 = t231 + t232;
    const float t234 = t226 * t215;
    const float t235 = t229 * t221;
    const float t236 = t234 + t235;
    const float t237 = 0.057887506f;
    const float t238 = t230 + t237;
    const float t239 = 1.4054016e-5f;
    const float t240 = t236 + t239;
    out[0] = t14;
    out[1] = t16;
    out[2] = t198;
    out[3] = t204;
    out[4] = t238;
    out[5] = t233;
    out[6] = t240;
    out[7] = t18;
}

/* One EKF sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's ekf_unmeasured. */
static void ekf_unmeasured(const float *x, const float *p, const float *u, float *out) {
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 1.0f;
    const float t6 = 2.0f;
    const float t7 = 6.0f;
    const float t8 = t5 / t6;
    const float t9 = t5 / t7;
    const float t10 = 0.178f /* a1 */;
    const float t11 = 981.0f /* g */;
    const float t12 = t6 * t11;
    const float t13 = fabsf(t0);
    const float t14 = t12 * t13;
    const float t15 = sqrtf(t14);
    const float t16 = t10 * t15;
    const float t17 = 0.5f;
    const float t18 = t17 / t15;
    const float t19 = signum(t0);
    const float t20 = t12 * t19;
    const float t21 = t18 * t20;
    const float t22 = t10 * t21;
    const float t23 = 0.178f /* a2 */;
    const float t24 = fabsf(t1);
    const float t25 = t12 * t24;
    const float t26 = sqrtf(t25);
    const float t27 = t23 * t26;
    const float t28 = t17 / t26;
    const float t29 = signum(t1);
    const float t30 = t12 * t29;
    const float t31 = t28 * t30;
    const float t32 = t23 * t31;
    const float t33 = 3.3f /* k */;
    const float t34 = u[0];
    const float t35 = t33 * t34;
    const float t36 = t35 - t16;
    const float t37 = 15.5f /* A1 */;
    const float t38 = t36 / t37;
    const float t39 = -1.0f;
    const float t40 = t39 / t37;
    const float t41 = t40 * t22;
    const float t42 = t16 - t27;
    const float t43 = 15.5f /* A2 */;
    const float t44 = t42 / t43;
    const float t45 = t5 / t43;
    const float t46 = t45 * t22;
    const float t47 = t39 / t43;
    const float t48 = t47 * t32;
    const float t49 = t8 * t38;
    const float t50 = t0 + t49;
    const float t51 = t8 * t44;
    const float t52 = t1 + t51;
    const float t53 = t8 * t41;
    const float t54 = t5 + t53;
    const float t55 = t8 * t46;
    const float t56 = t8 * t48;
    const float t57 = t5 + t56;
    const float t58 = fabsf(t50);
    const float t59 = t12 * t58;
    const float t60 = sqrtf(t59);
    const float t61 = t10 * t60;
    const float t62 = t17 / t60;
    const float t63 = signum(t50);
    const float t64 = t12 * t63;
    const float t65 = t62 * t64;
    const float t66 = t10 * t65;
    const float t67 = fabsf(t52);
    const float t68 = t12 * t67;
    const float t69 = sqrtf(t68);
    const float t70 = t23 * t69;
    const float t71 = t17 / t69;
    const float t72 = signum(t52);
    const float t73 = t12 * t72;
    const float t74 = t71 * t73;
    const float t75 = t23 * t74;
    const float t76 = t35 - t61;
    const float t77 = t76 / t37;
    const float t78 = t40 * t66;
    const float t79 = t61 - t70;
    const float t80 = t79 / t43;
    const float t81 = t45 * t66;
    const float t82 = t47 * t75;
    const float t83 = t78 * t54;
    const float t84 = t81 * t54;
    const float t85 = t82 * t55;
    const float t86 = t84 + t85;
    const float t87 = t82 * t57;
    const float t88 = t8 * t77;
    const float t89 = t0 + t88;
    const float t90 = t8 * t80;
    const float t91 = t1 + t90;
    const float t92 = t8 * t83;
    const float t93 = t5 + t92;
    const float t94 = t8 * t86;
    const float t95 = t8 * t87;
    const float t96 = t5 + t95;
    const float t97 = fabsf(t89);
    const float t98 = t12 * t97;
    const float t99 = sqrtf(t98);
    const float t100 = t10 * t99;
    const float t101 = t17 / t99;
    const float t102 = signum(t89);
    const float t103 = t12 * t102;
    const float t104 = t101 * t103;
    const float t105 = t10 * t104;
    const float t106 = fabsf(t91);
    const float t107 = t12 * t106;
    const float t108 = sqrtf(t107);
    const float t109 = t23 * t108;
    const float t110 = t17 / t108;
    const float t111 = signum(t91);
    const float t112 = t12 * t111;
    const float t113 = t110 * t112;
    const float t114 = t23 * t113;
    const float t115 = t35 - t100;
    const float t116 = t115 / t37;
    const float t117 = t40 * t105;
    const float t118 = t100 - t109;
    const float t119 = t118 / t43;
    const float t120 = t45 * t105;
    const float t121 = t47 * t114;
    const float t122 = t117 * t93;
    const float t123 = t120 * t93;
    const float t124 = t121 * t94;
    const float t125 = t123 + t124;
    const float t126 = t121 * t96;
    const float t127 = t0 + t116;
    const float t128 = t1 + t119;
    const float t129 = t5 + t122;
    const float t130 = t5 + t126;
    const float t131 = fabsf(t127);
    const float t132 = t12 * t131;
    const float t133 = sqrtf(t132);
    const float t134 = t10 * t133;
    const float t135 = t17 / t133;
    const float t136 = signum(t127);
    const float t137 = t12 * t136;
    const float t138 = t135 * t137;
    const float t139 = t10 * t138;
    const float t140 = fabsf(t128);
    const float t141 = t12 * t140;
    const float t142 = sqrtf(t141);
    const float t143 = t23 * t142;
    const float t144 = t17 / t142;
    const float t145 = signum(t128);
    const float t146 = t12 * t145;
    const float t147 = t144 * t146;
    const float t148 = t23 * t147;
    const float t149 = t35 - t134;
    const float t150 = t149 / t37;
    const float t151 = t40 * t139;
    const float t152 = t134 - t143;
    const float t153 = t152 / t43;
    const float t154 = t45 * t139;
    const float t155 = t47 * t148;
    const float t156 = t151 * t129;
    const float t157 = t154 * t129;
    const float t158 = t155 * t125;
    const float t159 = t157 + t158;
    const float t160 = t155 * t130;
    const float t161 = t77 + t116;
    const float t162 = t6 * t161;
    const float t163 = t38 + t162;
    const float t164 = t163 + t150;
    const float t165 = t9 * t164;
    const float t166 = t0 + t165;
    const float t167 = t80 + t119;
    const float t168 = t6 * t167;
    const float t169 = t44 + t168;
    const float t170 = t169 + t153;
    const float t171 = t9 * t170;
    const float t172 = t1 + t171;
    const float t173 = t83 + t122;
    const float t174 = t6 * t173;
    const float t175 = t41 + t174;
    const float t176 = t175 + t156;
    const float t177 = t9 * t176;
    const float t178 = t5 + t177;
    const float t179 = t86 + t125;
    const float t180 = t6 * t179;
    const float t181 = t46 + t180;
    const float t182 = t181 + t159;
    const float t183 = t9 * t182;
    const float t184 = t87 + t126;
    const float t185 = t6 * t184;
    const float t186 = t48 + t185;
    const float t187 = t186 + t160;
    const float t188 = t9 * t187;
    const float t189 = t5 + t188;
    const float t190 = t178 * t2;
    const float t191 = t178 * t3;
    const float t192 = t183 * t2;
    const float t193 = t189 * t3;
    const float t194 = t192 + t193;
    const float t195 = t183 * t3;
    const float t196 = t189 * t4;
    const float t197 = t195 + t196;
    const float t198 = t190 * t178;
    const float t199 = t190 * t183;
    const float t200 = t191 * t189;
    const float t201 = t199 + t200;
    const float t202 = t194 * t183;
    const float t203 = t197 * t189;
    const float t204 = t202 + t203;
    const float t205 = 0.057887506f;
    const float t206 = t198 + t205;
    const float t207 = 1.4054016e-5f;
    const float t208 = t204 + t207;
    out[0] = t166;
    out[1] = t172;
    out[2] = t206;
    out[3] = t201;
    out[4] = t208;
}

/* The EKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float EKF_X0[TWO_TANKS_STATES] = {
    15.0f, 15.0f
};
static const float EKF_P0[TWO_TANKS_COVARIANCE] = {
    37.50865f, 0.0f, 453.69177f
};

/* The EKF's prediction alone (a lost output), taken when finite. */
static void ekf_predict(float *x, float *p, const float *u) {
    float out[TWO_TANKS_STATES + TWO_TANKS_COVARIANCE];
    ekf_unmeasured(x, p, u, out);
    if (all_finite(out, TWO_TANKS_STATES + TWO_TANKS_COVARIANCE)) {
        memcpy(x, out, TWO_TANKS_STATES * sizeof *x);
        memcpy(p, out + TWO_TANKS_STATES, TWO_TANKS_COVARIANCE * sizeof *p);
    }
}

/* The EKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ekf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * TWO_TANKS_STATES + TWO_TANKS_COVARIANCE + 1u];
    ekf_measured(x, p, y, u, out);
    if (!all_finite(out + TWO_TANKS_STATES, TWO_TANKS_STATES + TWO_TANKS_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * TWO_TANKS_STATES + TWO_TANKS_COVARIANCE];
    memcpy(estimate, out, TWO_TANKS_STATES * sizeof *x);
    memcpy(x, out + TWO_TANKS_STATES, TWO_TANKS_STATES * sizeof *x);
    memcpy(p, out + 2u * TWO_TANKS_STATES, TWO_TANKS_COVARIANCE * sizeof *p);
    return 1;
}


static void ekf_box_fresh(two_tanks_ekf_box *o) {
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

static two_tanks_status ekf_box_sample(two_tanks_ekf_box *o, const float *y, const float *u) {
    float estimate[TWO_TANKS_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return TWO_TANKS_REFUSED;
    }
    if (!accepts(y, u)) {
        ekf_predict(o->x, o->p, u);
        return TWO_TANKS_REFUSED;
    }
    if (!ekf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ekf_box_fresh(o);
        return TWO_TANKS_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.1f * (nis - o->chi);
    if (!(o->chi <= 1024.0f)) {
        ekf_box_fresh(o);
        return TWO_TANKS_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < TWO_TANKS_TARGETS; ++i) {
        o->flags[i] = TWO_TANKS_INSIDE;
    }
    o->ready = 1;
    return TWO_TANKS_OK;
}

void two_tanks_ekf_box_init(two_tanks_ekf_box *o) {
    ekf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

two_tanks_status two_tanks_ekf_box_push(two_tanks_ekf_box *o, const float *y, const float *u) {
    const two_tanks_status status = ekf_box_sample(o, y, u);
    if (status == TWO_TANKS_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == TWO_TANKS_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

two_tanks_status two_tanks_ekf_box_estimate(const two_tanks_ekf_box *o, float *values, two_tanks_saturation *saturation) {
    if (!o->ready) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return TWO_TANKS_OK;
}

/* One UKF sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's ukf_measured. */
static void ukf_measured(const float *x, const float *p, const float *y, const float *u, float *out) {
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 1.0f;
    const float t6 = 1.1920929e-7f;
    const float t7 = fabsf(t2);
    const float t8 = t6 * t7;
    const float t9 = 1.1754944e-38f;
    const float t10 = t8 + t9;
    const float t11 = select_float(!(t2 >= t10), t10, t2);
    const float t12 = sqrtf(t11);
    const float t13 = t5 / t12;
    const float t14 = t3 * t13;
    const float t15 = t14 * t14;
    const float t16 = t4 - t15;
    const float t17 = fabsf(t4);
    const float t18 = t6 * t17;
    const float t19 = t18 + t9;
    const float t20 = select_float(!(t16 >= t19), t19, t16);
    const float t21 = sqrtf(t20);
    const float t22 = 1.4142135f;
    const float t23 = t22 * t12;
    const float t24 = t0 + t23;
    const float t25 = t22 * t14;
    const float t26 = t1 + t25;
    const float t27 = t22 * t21;
    const float t28 = t1 + t27;
    const float t29 = -1.4142135f;
    const float t30 = t29 * t12;
    const float t31 = t0 + t30;
    const float t32 = t29 * t14;
    const float t33 = t1 + t32;
    const float t34 = t29 * t21;
    const float t35 = t1 + t34;
    const float t36 = 0.25f;
    const float t37 = t26 + t28;
    const float t38 = t37 + t33;
    const float t39 = t38 + t35;
    const float t40 = t36 * t39;
    const float t41 = t26 - t40;
    const float t42 = t28 - t40;
    const float t43 = t33 - t40;
    const float t44 = t35 - t40;
    const float t45 = t24 - t0;
    const float t46 = t26 - t1;
    const float t47 = t28 - t1;
    const float t48 = t31 - t0;
    const float t49 = t33 - t1;
    const float t50 = t35 - t1;
    const float t51 = t41 * t41;
    const float t52 = t42 * t42;
    const float t53 = t51 + t52;
    const float t54 = t43 * t43;
    const float t55 = t53 + t54;
    const float t56 = t44 * t44;
    const float t57 = t55 + t56;
    const float t58 = t36 * t57;
    const float t59 = 0.04f;
    const float t60 = t58 + t59;
    const float t61 = t45 * t41;
    const float t62 = t48 * t43;
    const float t63 = t61 + t62;
    const float t64 = t36 * t63;
    const float t65 = t46 * t41;
    const float t66 = t47 * t42;
    const float t67 = t65 + t66;
    const float t68 = t49 * t43;
    const float t69 = t67 + t68;
    const float t70 = t50 * t44;
    const float t71 = t69 + t70;
    const float t72 = t36 * t71;
    const float t73 = fabsf(t60);
    const float t74 = t6 * t73;
    const float t75 = t74 + t9;
    const float t76 = select_float(!(t60 >= t75), t75, t60);
    const float t77 = sqrtf(t76);
    const float t78 = t5 / t77;
    const float t79 = t64 * t78;
    const float t80 = t79 * t78;
    const float t81 = t72 * t78;
    const float t82 = t81 * t78;
    const float t83 = y[0];
    const float t84 = t83 - t40;
    const float t85 = t80 * t84;
    const float t86 = t0 + t85;
    const float t87 = t82 * t84;
    const float t88 = t1 + t87;
    const float t89 = t84 * t78;
    const float t90 = t89 * t89;
    const float t91 = t64 * t80;
    const float t92 = t2 - t91;
    const float t93 = t64 * t82;
    const float t94 = t3 - t93;
    const float t95 = t72 * t82;
    const float t96 = t4 - t95;
    const float t97 = fabsf(t92);
    const float t98 = t6 * t97;
    const float t99 = t98 + t9;
    const float t100 = select_float(!(t92 >= t99), t99, t92);
    const float t101 = sqrtf(t100);
    const float t102 = t5 / t101;
    const float t103 = t94 * t102;
    const float t104 = t103 * t103;
    const float t105 = t96 - t104;
    const float t106 = fabsf(t96);
    const float t107 = t6 * t106;
    const float t108 = t107 + t9;
    const float t109 = select_float(!(t105 >= t108), t108, t105);
    const float t110 = sqrtf(t109);
    const float t111 = t22 * t101;
    const float t112 = t86 + t111;
    const float t113 = t22 * t103;
    const float t114 = t88 + t113;
    const float t115 = t22 * t110;
    const float t116 = t88 + t115;
    const float t117 = t29 * t101;
    const float t118 = t86 + t117;
    const float t119 = t29 * t103;
    const float t120 = t88 + t119;
    const float t121 = t29 * t110;
    const float t122 = t88 + t121;
    const float t123 = 2.0f;
    const float t124 = 6.0f;
    const float t125 = t5 / t123;
    const float t126 = t5 / t124;
    const float t127 = 0.178f /* a1 */;
    const float t128 = 981.0f /* g */;
    const float t129 = t123 * t128;
    const float t130 = fabsf(t112);
    const float t131 = t129 * t130;
    const float t132 = sqrtf(t131);
    const float t133 = t127 * t132;
    const float t134 = 0.178f /* a2 */;
    const float t135 = fabsf(t114);
    const float t136 = t129 * t135;
    const float t137 = sqrtf(t136);
    const float t138 = t134 * t137;
    const float t139 = 3.3f /* k */;
    const float t140 = u[0];
    const float t141 = t139 * t140;
    const float t142 = t141 - t133;
    const float t143 = 15.5f /* A1 */;
    const float t144 = t142 / t143;
    const float t145 = t133 - t138;
    const float t146 = 15.5f /* A2 */;
    const float t147 = t145 / t146;
    const float t148 = t125 * t144;
    const float t149 = t112 + t148;
    const float t150 = t125 * t147;
    const float t151 = t114 + t150;
    const float t152 = fabsf(t149);
    const float t153 = t129 * t152;
    const float t154 = sqrtf(t153);
    const float t155 = t127 * t154;
    const float t156 = fabsf(t151);
    const float t157 = t129 * t156;
    const float t158 = sqrtf(t157);
    const float t159 = t134 * t158;
    const float t160 = t141 - t155;
    const float t161 = t160 / t143;
    const float t162 = t155 - t159;
    const float t163 = t162 / t146;
    const float t164 = t125 * t161;
    const float t165 = t112 + t164;
    const float t166 = t125 * t163;
    const float t167 = t114 + t166;
    const float t168 = fabsf(t165);
    const float t169 = t129 * t168;
    const float t170 = sqrtf(t169);
    const float t171 = t127 * t170;
    const float t172 = fabsf(t167);
    const float t173 = t129 * t172;
    const float t174 = sqrtf(t173);
    const float t175 = t134 * t174;
    const float t176 = t141 - t171;
    const float t177 = t176 / t143;
    const float t178 = t171 - t175;
    const float t179 = t178 / t146;
    const float t180 = t112 + t177;
    const float t181 = t114 + t179;
    const float t182 = fabsf(t180);
    const float t183 = t129 * t182;
    const float t184 = sqrtf(t183);
    const float t185 = t127 * t184;
    const float t186 = fabsf(t181);
    const float t187 = t129 * t186;
    const float t188 = sqrtf(t187);
    const float t189 = t134 * t188;
    const float t190 = t141 - t185;
    const float t191 = t190 / t143;
    const float t192 = t185 - t189;
    const float t193 = t192 / t146;
    const float t194 = t161 + t177;
    const float t195 = t123 * t194;
    const float t196 = t144 + t195;
    const float t197 = t196 + t191;
    const float t198 = t126 * t197;
    const float t199 = t112 + t198;
    const float t200 = t163 + t179;
    const float t201 = t123 * t200;
    const float t202 = t147 + t201;
    const float t203 = t202 + t193;
    const float t204 = t126 * t203;
    const float t205 = t114 + t204;
    const float t206 = fabsf(t86);
    const float t207 = t129 * t206;
    const float t208 = sqrtf(t207);
    const float t209 = t127 * t208;
    const float t210 = fabsf(t116);
    const float t211 = t129 * t210;
    const float t212 = sqrtf(t211);
    const float t213 = t134 * t212;
    const float t214 = t141 - t209;
    const float t215 = t214 / t143;
    const float t216 = t209 - t213;
    const float t217 = t216 / t146;
    const float t218 = t125 * t215;
    const float t219 = t86 + t218;
    const float t220 = t125 * t217;
    const float t221 = t116 + t220;
    const float t222 = fabsf(t219);
    const float t223 = t129 * t222;
    const float t224 = sqrtf(t223);
    const float t225 = t127 * t224;
    const float t226 = fabsf(t221);
    const float t227 = t129 * t226;
    const float t228 = sqrtf(t227);
    const float t229 = t134 * t228;
    const float t230 = t141 - t225;
    const float t231 = t230 / t143;
    const float t232 = t225 - t229;
    const float t233 = t232 / t146;
    const float t234 = t125 * t231;
    const float t235 = t86 + t234;
    const float t236 = t125 * t233;
    const float t237 = t116 + t236;
    const float t238 = fabsf(t235);
    const float t239 = t129 * t238;
    const float t240 = sqrtf(t239);
    const float t241 = t127 * t240;
    const float t242 = fabsf(t237);
    const float t243 = t129 * t242;
    const float t244 = sqrtf(t243);
    const float t245 = t134 * t244;
    const float t246 = t141 - t241;
    const float t247 = t246 / t143;
    const float t248 = t241 - t245;
    const float t249 = t248 / t146;
    const float t250 = t86 + t247;
    const float t251 = t116 + t249;
    const float t252 = fabsf(t250);
    const float t253 = t129 * t252;
    const float t254 = sqrtf(t253);
    const float t255 = t127 * t254;
    const float t256 = fabsf(t251);
    const float t257 = t129 * t256;
    const float t258 = sqrtf(t257);
    const float t259 = t134 * t258;
    const float t260 = t141 - t255;
    const float t261 = t260 / t143;
    const float t262 = t255 - t259;
    const float t263 = t262 / t146;
    const float t264 = t231 + t247;
    const float t265 = t123 * t264;
    const float t266 = t215 + t265;
    const float t267 = t266 + t261;
    const float t268 = t126 * t267;
    const float t269 = t86 + t268;
    const float t270 = t233 + t249;
    const float t271 = t123 * t270;
    const float t272 = t217 + t271;
    const float t273 = t272 + t263;
    const float t274 = t126 * t273;
    const float t275 = t116 + t274;
    const float t276 = fabsf(t118);
    const float t277 = t129 * t276;
    const float t278 = sqrtf(t277);
    const float t279 = t127 * t278;
    const float t280 = fabsf(t120);
    const float t281 = t129 * t280;
    const float t282 = sqrtf(t281);
    const float t283 = t134 * t282;
    const float t284 = t141 - t279;
    const float t285 = t284 / t143;
    const float t286 = t279 - t283;
    const float t287 = t286 / t146;
    const float t288 = t125 * t285;
    const float t289 = t118 + t288;
    const float t290 = t125 * t287;
    const float t291 = t120 + t290;
    const float t292 = fabsf(t289);
    const float t293 = t129 * t292;
    const float t294 = sqrtf(t293);
    const float t295 = t127 * t294;
    const float t296 = fabsf(t291);
    const float t297 = t129 * t296;
    const float t298 = sqrtf(t297);
    const float t299 = t134 * t298;
    const float t300 = t141 - t295;
    const float t301 = t300 / t143;
    const float t302 = t295 - t299;
    const float t303 = t302 / t146;
    const float t304 = t125 * t301;
    const float t305 = t118 + t304;
    const float t306 = t125 * t303;
    const float t307 = t120 + t306;
    const float t308 = fabsf(t305);
    const float t309 = t129 * t308;
    const float t310 = sqrtf(t309);
    const float t311 = t127 * t310;
    const float t312 = fabsf(t307);
    const float t313 = t129 * t312;
    const float t314 = sqrtf(t313);
    const float t315 = t134 * t314;
    const float t316 = t141 - t311;
    const float t317 = t316 / t143;
    const float t318 = t311 - t315;
    const float t319 = t318 / t146;
    const float t320 = t118 + t317;
    const float t321 = t120 + t319;
    const float t322 = fabsf(t320);
    const float t323 = t129 * t322;
    const float t324 = sqrtf(t323);
    const float t325 = t127 * t324;
    const float t326 = fabsf(t321);
    const float t327 = t129 * t326;
    const float t328 = sqrtf(t327);
    const float t329 = t134 * t328;
    const float t330 = t141 - t325;
    const float t331 = t330 / t143;
    const float t332 = t325 - t329;
    const float t333 = t332 / t146;
    const float t334 = t301 + t317;
    const float t335 = t123 * t334;
    const float t336 = t285 + t335;
    const float t337 = t336 + t331;
    const float t338 = t126 * t337;
    const float t339 = t118 + t338;
    const float t340 = t303 + t319;
    const float t341 = t123 * t340;
    const float t342 = t287 + t341;
    const float t343 = t342 + t333;
    const float t344 = t126 * t343;
    const float t345 = t120 + t344;
    const float t346 = fabsf(t122);
    const float t347 = t129 * t346;
    const float t348 = sqrtf(t347);
    const float t349 = t134 * t348;
    const float t350 = t209 - t349;
    const float t351 = t350 / t146;
    const float t352 = t125 * t351;
    const float t353 = t122 + t352;
    const float t354 = fabsf(t353);
    const float t355 = t129 * t354;
    const float t356 = sqrtf(t355);
    const float t357 = t134 * t356;
    const float t358 = t225 - t357;
    const float t359 = t358 / t146;
    const float t360 = t125 * t359;
    const float t361 = t122 + t360;
    const float t362 = fabsf(t361);
    const float t363 = t129 * t362;
    const float t364 = sqrtf(t363);
    const float t365 = t134 * t364;
    const float t366 = t241 - t365;
    const float t367 = t366 / t146;
    const float t368 = t122 + t367;
    const float t369 = fabsf(t368);
    const float t370 = t129 * t369;
    const float t371 = sqrtf(t370);
    const float t372 = t134 * t371;
    const float t373 = t255 - t372;
    const float t374 = t373 / t146;
    const float t375 = t359 + t367;
    const float t376 = t123 * t375;
    const float t377 = t351 + t376;
    const float t378 = t377 + t374;
    const float t379 = t126 * t378;
    const float t380 = t122 + t379;
    const float t381 = t199 + t269;
    const float t382 = t381 + t339;
    const float t383 = t382 + t269;
    const float t384 = t36 * t383;
    const float t385 = t205 + t275;
    const float t386 = t385 + t345;
    const float t387 = t386 + t380;
    const float t388 = t36 * t387;
    const float t389 = t199 - t384;
    const float t390 = t205 - t388;
    const float t391 = t269 - t384;
    const float t392 = t275 - t388;
    const float t393 = t339 - t384;
    const float t394 = t345 - t388;
    const float t395 = t380 - t388;
    const float t396 = t389 * t389;
    const float t397 = t391 * t391;
    const float t398 = t396 + t397;
    const float t399 = t393 * t393;
    const float t400 = t398 + t399;
    const float t401 = t400 + t397;
    const float t402 = t36 * t401;
    const float t403 = t389 * t390;
    const float t404 = t391 * t392;
    const float t405 = t403 + t404;
    const float t406 = t393 * t394;
    const float t407 = t405 + t406;
    const float t408 = t391 * t395;
    const float t409 = t407 + t408;
    const float t410 = t36 * t409;
    const float t411 = t390 * t390;
    const float t412 = t392 * t392;
    const float t413 = t411 + t412;
    const float t414 = t394 * t394;
    const float t415 = t413 + t414;
    const float t416 = t395 * t395;
    const float t417 = t415 + t416;
    const float t418 = t36 * t417;
    const float t419 = 0.056878302f;
    const float t420 = t402 + t419;
    const float t421 = 1.4551619e-5f;
    const float t422 = t418 + t421;
    out[0] = t86;
    out[1] = t88;
    out[2] = t384;
    out[3] = t388;
    out[4] = t420;
    out[5] = t410;
    out[6] = t422;
    out[7] = t90;
}

/* One UKF sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's ukf_unmeasured. */
static void ukf_unmeasured(const float *x, const float *p, const float *u, float *out) {
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 1.0f;
    const float t6 = 1.1920929e-7f;
    const float t7 = fabsf(t2);
    const float t8 = t6 * t7;
    const float t9 = 1.1754944e-38f;
    const float t10 = t8 + t9;
    const float t11 = select_float(!(t2 >= t10), t10, t2);
    const float t12 = sqrtf(t11);
    const float t13 = t5 / t12;
    const float t14 = t3 * t13;
    const float t15 = t14 * t14;
    const float t16 = t4 - t15;
    const float t17 = fabsf(t4);
    const float t18 = t6 * t17;
    const float t19 = t18 + t9;
    const float t20 = select_float(!(t16 >= t19), t19, t16);
    const float t21 = sqrtf(t20);
    const float t22 = 1.4142135f;
    const float t23 = t22 * t12;
    const float t24 = t0 + t23;
    const float t25 = t22 * t14;
    const float t26 = t1 + t25;
    const float t27 = t22 * t21;
    const float t28 = t1 + t27;
    const float t29 = -1.4142135f;
    const float t30 = t29 * t12;
    const float t31 = t0 + t30;
    const float t32 = t29 * t14;
    const float t33 = t1 + t32;
    const float t34 = t29 * t21;
    const float t35 = t1 + t34;
    const float t36 = 2.0f;
    const float t37 = 6.0f;
    const float t38 = t5 / t36;
    const float t39 = t5 / t37;
    const float t40 = 0.178f /* a1 */;
    const float t41 = 981.0f /* g */;
    const float t42 = t36 * t41;
    const float t43 = fabsf(t24);
    const float t44 = t42 * t43;
    const float t45 = sqrtf(t44);
    const float t46 = t40 * t45;
    const float t47 = 0.178f /* a2 */;
    const float t48 = fabsf(t26);
    const float t49 = t42 * t48;
    const float t50 = sqrtf(t49);
    const float t51 = t47 * t50;
    const float t52 = 3.3f /* k */;
    const float t53 = u[0];
    const float t54 = t52 * t53;
    const float t55 = t54 - t46;
    const float t56 = 15.5f /* A1 */;
    const float t57 = t55 / t56;
    const float t58 = t46 - t51;
    const float t59 = 15.5f /* A2 */;
    const float t60 = t58 / t59;
    const float t61 = t38 * t57;
    const float t62 = t24 + t61;
    const float t63 = t38 * t60;
    const float t64 = t26 + t63;
    const float t65 = fabsf(t62);
    const float t66 = t42 * t65;
    const float t67 = sqrtf(t66);
    const float t68 = t40 * t67;
    const float t69 = fabsf(t64);
    const float t70 = t42 * t69;
    const float t71 = sqrtf(t70);
    const float t72 = t47 * t71;
    const float t73 = t54 - t68;
    const float t74 = t73 / t56;
    const float t75 = t68 - t72;
    const float t76 = t75 / t59;
    const float t77 = t38 * t74;
    const float t78 = t24 + t77;
    const float t79 = t38 * t76;
    const float t80 = t26 + t79;
    const float t81 = fabsf(t78);
    const float t82 = t42 * t81;
    const float t83 = sqrtf(t82);
    const float t84 = t40 * t83;
    const float t85 = fabsf(t80);
    const float t86 = t42 * t85;
    const float t87 = sqrtf(t86);
    const float t88 = t47 * t87;
    const float t89 = t54 - t84;
    const float t90 = t89 / t56;
    const float t91 = t84 - t88;
    const float t92 = t91 / t59;
    const float t93 = t24 + t90;
    const float t94 = t26 + t92;
    const float t95 = fabsf(t93);
    const float t96 = t42 * t95;
    const float t97 = sqrtf(t96);
    const float t98 = t40 * t97;
    const float t99 = fabsf(t94);
    const float t100 = t42 * t99;
    const float t101 = sqrtf(t100);
    const float t102 = t47 * t101;
    const float t103 = t54 - t98;
    const float t104 = t103 / t56;
    const float t105 = t98 - t102;
    const float t106 = t105 / t59;
    const float t107 = t74 + t90;
    const float t108 = t36 * t107;
    const float t109 = t57 + t108;
    const float t110 = t109 + t104;
    const float t111 = t39 * t110;
    const float t112 = t24 + t111;
    const float t113 = t76 + t92;
    const float t114 = t36 * t113;
    const float t115 = t60 + t114;
    const float t116 = t115 + t106;
    const float t117 = t39 * t116;
    const float t118 = t26 + t117;
    const float t119 = fabsf(t0);
    const float t120 = t42 * t119;
    const float t121 = sqrtf(t120);
    const float t122 = t40 * t121;
    const float t123 = fabsf(t28);
    const float t124 = t42 * t123;
    const float t125 = sqrtf(t124);
    const float t126 = t47 * t125;
    const float t127 = t54 - t122;
    const float t128 = t127 / t56;
    const float t129 = t122 - t126;
    const float t130 = t129 / t59;
    const float t131 = t38 * t128;
    const float t132 = t0 + t131;
    const float t133 = t38 * t130;
    const float t134 = t28 + t133;
    const float t135 = fabsf(t132);
    const float t136 = t42 * t135;
    const float t137 = sqrtf(t136);
    const float t138 = t40 * t137;
    const float t139 = fabsf(t134);
    const float t140 = t42 * t139;
    const float t141 = sqrtf(t140);
    const float t142 = t47 * t141;
    const float t143 = t54 - t138;
    const float t144 = t143 / t56;
    const float t145 = t138 - t142;
    const float t146 = t145 / t59;
    const float t147 = t38 * t144;
    const float t148 = t0 + t147;
    const float t149 = t38 * t146;
    const float t150 = t28 + t149;
    const float t151 = fabsf(t148);
    const float t152 = t42 * t151;
    const float t153 = sqrtf(t152);
    const float t154 = t40 * t153;
    const float t155 = fabsf(t150);
    const float t156 = t42 * t155;
    const float t157 = sqrtf(t156);
    const float t158 = t47 * t157;
    const float t159 = t54 - t154;
    const float t160 = t159 / t56;
    const float t161 = t154 - t158;
    const float t162 = t161 / t59;
    const float t163 = t0 + t160;
    const float t164 = t28 + t162;
    const float t165 = fabsf(t163);
    const float t166 = t42 * t165;
    const float t167 = sqrtf(t166);
    const float t168 = t40 * t167;
    const float t169 = fabsf(t164);
    const float t170 = t42 * t169;
    const float t171 = sqrtf(t170);
    const float t172 = t47 * t171;
    const float t173 = t54 - t168;
    const float t174 = t173 / t56;
    const float t175 = t168 - t172;
    const float t176 = t175 / t59;
    const float t177 = t144 + t160;
    const float t178 = t36 * t177;
    const float t179 = t128 + t178;
    const float t180 = t179 + t174;
    const float t181 = t39 * t180;
    const float t182 = t0 + t181;
    const float t183 = t146 + t162;
    const float t184 = t36 * t183;
    const float t185 = t130 + t184;
    const float t186 = t185 + t176;
    const float t187 = t39 * t186;
    const float t188 = t28 + t187;
    const float t189 = fabsf(t31);
    const float t190 = t42 * t189;
    const float t191 = sqrtf(t190);
    const float t192 = t40 * t191;
    const float t193 = fabsf(t33);
    const float t194 = t42 * t193;
    const float t195 = sqrtf(t194);
    const float t196 = t47 * t195;
    const float t197 = t54 - t192;
    const float t198 = t197 / t56;
    const float t199 = t192 - t196;
    const float t200 = t199 / t59;
    const float t201 = t38 * t198;
    const float t202 = t31 + t201;
    const float t203 = t38 * t200;
    const float t204 = t33 + t203;
    const float t205 = fabsf(t202);
    const float t206 = t42 * t205;
    const float t207 = sqrtf(t206);
    const float t208 = t40 * t207;
    const float t209 = fabsf(t204);
    const float t210 = t42 * t209;
    const float t211 = sqrtf(t210);
    const float t212 = t47 * t211;
    const float t213 = t54 - t208;
    const float t214 = t213 / t56;
    const float t215 = t208 - t212;
    const float t216 = t215 / t59;
    const float t217 = t38 * t214;
    const float t218 = t31 + t217;
    const float t219 = t38 * t216;
    const float t220 = t33 + t219;
    const float t221 = fabsf(t218);
    const float t222 = t42 * t221;
    const float t223 = sqrtf(t222);
    const float t224 = t40 * t223;
    const float t225 = fabsf(t220);
    const float t226 = t42 * t225;
    const float t227 = sqrtf(t226);
    const float t228 = t47 * t227;
    const float t229 = t54 - t224;
    const float t230 = t229 / t56;
    const float t231 = t224 - t228;
    const float t232 = t231 / t59;
    const float t233 = t31 + t230;
    const float t234 = t33 + t232;
    const float t235 = fabsf(t233);
    const float t236 = t42 * t235;
    const float t237 = sqrtf(t236);
    const float t238 = t40 * t237;
    const float t239 = fabsf(t234);
    const float t240 = t42 * t239;
    const float t241 = sqrtf(t240);
    const float t242 = t47 * t241;
    const float t243 = t54 - t238;
    const float t244 = t243 / t56;
    const float t245 = t238 - t242;
    const float t246 = t245 / t59;
    const float t247 = t214 + t230;
    const float t248 = t36 * t247;
    const float t249 = t198 + t248;
    const float t250 = t249 + t244;
    const float t251 = t39 * t250;
    const float t252 = t31 + t251;
    const float t253 = t216 + t232;
    const float t254 = t36 * t253;
    const float t255 = t200 + t254;
    const float t256 = t255 + t246;
    const float t257 = t39 * t256;
    const float t258 = t33 + t257;
    const float t259 = fabsf(t35);
    const float t260 = t42 * t259;
    const float t261 = sqrtf(t260);
    const float t262 = t47 * t261;
    const float t263 = t122 - t262;
    const float t264 = t263 / t59;
    const float t265 = t38 * t264;
    const float t266 = t35 + t265;
    const float t267 = fabsf(t266);
    const float t268 = t42 * t267;
    const float t269 = sqrtf(t268);
    const float t270 = t47 * t269;
    const float t271 = t138 - t270;
    const float t272 = t271 / t59;
    const float t273 = t38 * t272;
    const float t274 = t35 + t273;
    const float t275 = fabsf(t274);
    const float t276 = t42 * t275;
    const float t277 = sqrtf(t276);
    const float t278 = t47 * t277;
    const float t279 = t154 - t278;
    const float t280 = t279 / t59;
    const float t281 = t35 + t280;
    const float t282 = fabsf(t281);
    const float t283 = t42 * t282;
    const float t284 = sqrtf(t283);
    const float t285 = t47 * t284;
    const float t286 = t168 - t285;
    const float t287 = t286 / t59;
    const float t288 = t272 + t280;
    const float t289 = t36 * t288;
    const float t290 = t264 + t289;
    const float t291 = t290 + t287;
    const float t292 = t39 * t291;
    const float t293 = t35 + t292;
    const float t294 = 0.25f;
    const float t295 = t112 + t182;
    const float t296 = t295 + t252;
    const float t297 = t296 + t182;
    const float t298 = t294 * t297;
    const float t299 = t118 + t188;
    const float t300 = t299 + t258;
    const float t301 = t300 + t293;
    const float t302 = t294 * t301;
    const float t303 = t112 - t298;
    const float t304 = t118 - t302;
    const float t305 = t182 - t298;
    const float t306 = t188 - t302;
    const float t307 = t252 - t298;
    const float t308 = t258 - t302;
    const float t309 = t293 - t302;
    const float t310 = t303 * t303;
    const float t311 = t305 * t305;
    const float t312 = t310 + t311;
    const float t313 = t307 * t307;
    const float t314 = t312 + t313;
    const float t315 = t314 + t311;
    const float t316 = t294 * t315;
    const float t317 = t303 * t304;
    const float t318 = t305 * t306;
    const float t319 = t317 + t318;
    const float t320 = t307 * t308;
    const float t321 = t319 + t320;
    const float t322 = t305 * t309;
    const float t323 = t321 + t322;
    const float t324 = t294 * t323;
    const float t325 = t304 * t304;
    const float t326 = t306 * t306;
    const float t327 = t325 + t326;
    const float t328 = t308 * t308;
    const float t329 = t327 + t328;
    const float t330 = t309 * t309;
    const float t331 = t329 + t330;
    const float t332 = t294 * t331;
    const float t333 = 0.056878302f;
    const float t334 = t316 + t333;
    const float t335 = 1.4551619e-5f;
    const float t336 = t332 + t335;
    out[0] = t298;
    out[1] = t302;
    out[2] = t334;
    out[3] = t324;
    out[4] = t336;
}

/* The UKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float UKF_X0[TWO_TANKS_STATES] = {
    15.0f, 15.0f
};
static const float UKF_P0[TWO_TANKS_COVARIANCE] = {
    6.996126f, 0.0f, 3716.8132f
};

/* The UKF's prediction alone (a lost output), taken when finite. */
static void ukf_predict(float *x, float *p, const float *u) {
    float out[TWO_TANKS_STATES + TWO_TANKS_COVARIANCE];
    ukf_unmeasured(x, p, u, out);
    if (all_finite(out, TWO_TANKS_STATES + TWO_TANKS_COVARIANCE)) {
        memcpy(x, out, TWO_TANKS_STATES * sizeof *x);
        memcpy(p, out + TWO_TANKS_STATES, TWO_TANKS_COVARIANCE * sizeof *p);
    }
}

/* The UKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ukf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * TWO_TANKS_STATES + TWO_TANKS_COVARIANCE + 1u];
    ukf_measured(x, p, y, u, out);
    if (!all_finite(out + TWO_TANKS_STATES, TWO_TANKS_STATES + TWO_TANKS_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * TWO_TANKS_STATES + TWO_TANKS_COVARIANCE];
    memcpy(estimate, out, TWO_TANKS_STATES * sizeof *x);
    memcpy(x, out + TWO_TANKS_STATES, TWO_TANKS_STATES * sizeof *x);
    memcpy(p, out + 2u * TWO_TANKS_STATES, TWO_TANKS_COVARIANCE * sizeof *p);
    return 1;
}


static void ukf_box_fresh(two_tanks_ukf_box *o) {
    memcpy(o->x, UKF_X0, sizeof o->x);
    memcpy(o->p, UKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

static two_tanks_status ukf_box_sample(two_tanks_ukf_box *o, const float *y, const float *u) {
    float estimate[TWO_TANKS_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return TWO_TANKS_REFUSED;
    }
    if (!accepts(y, u)) {
        ukf_predict(o->x, o->p, u);
        return TWO_TANKS_REFUSED;
    }
    if (!ukf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ukf_box_fresh(o);
        return TWO_TANKS_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.1f * (nis - o->chi);
    if (!(o->chi <= 1024.0f)) {
        ukf_box_fresh(o);
        return TWO_TANKS_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < TWO_TANKS_TARGETS; ++i) {
        o->flags[i] = TWO_TANKS_INSIDE;
    }
    o->ready = 1;
    return TWO_TANKS_OK;
}

void two_tanks_ukf_box_init(two_tanks_ukf_box *o) {
    ukf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

two_tanks_status two_tanks_ukf_box_push(two_tanks_ukf_box *o, const float *y, const float *u) {
    const two_tanks_status status = ukf_box_sample(o, y, u);
    if (status == TWO_TANKS_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == TWO_TANKS_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

two_tanks_status two_tanks_ukf_box_estimate(const two_tanks_ukf_box *o, float *values, two_tanks_saturation *saturation) {
    if (!o->ready) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return TWO_TANKS_OK;
}

/* The start-up schedule, j = 1 … 30: the blends g_j per state, then the gains K_j (states x
 * outputs, row by row). */
static const float CORRECTED_BLENDS[30][4] = {
{
    0.10935951f, 0.10935951f, 0.6941791f, 0.07725346f
},
{
    0.05784257f, 0.05784257f, 0.70379144f, 0.08816933f
},
{
    0.039319836f, 0.039319836f, 0.70724756f, 0.09209409f
},
{
    0.029782638f, 0.029782638f, 0.70902705f, 0.09411492f
},
{
    0.023968881f, 0.023968881f, 0.71011186f, 0.09534679f
},
{
    0.02005418f, 0.02005418f, 0.71084225f, 0.09617628f
},
{
    0.017238684f, 0.017238684f, 0.7113676f, 0.09677285f
},
{
    0.015116422f, 0.015116422f, 0.71176356f, 0.09722254f
},
{
    0.013459426f, 0.013459426f, 0.71207273f, 0.09757364f
},
{
    0.01212981f, 0.01212981f, 0.71232086f, 0.09785537f
},
{
    0.011039273f, 0.011039273f, 0.71252435f, 0.09808644f
},
{
    0.010128651f, 0.010128651f, 0.7126942f, 0.09827939f
},
{
    0.009356814f, 0.009356814f, 0.71283823f, 0.098442934f
},
{
    0.008694281f, 0.008694281f, 0.71296185f, 0.09858332f
},
{
    0.008119369f, 0.008119369f, 0.71306914f, 0.098705135f
},
{
    0.007615773f, 0.007615773f, 0.7131631f, 0.09881184f
},
{
    0.0071709985f, 0.0071709985f, 0.7132461f, 0.098906085f
},
{
    0.0067753093f, 0.0067753093f, 0.7133199f, 0.09898993f
},
{
    0.0064210035f, 0.0064210035f, 0.71338606f, 0.099065f
},
{
    0.0061019124f, 0.0061019124f, 0.71344554f, 0.09913261f
},
{
    0.0058130343f, 0.0058130343f, 0.7134995f, 0.09919382f
},
{
    0.005550272f, 0.005550272f, 0.7135485f, 0.0992495f
},
{
    0.0053102374f, 0.0053102374f, 0.7135933f, 0.09930036f
},
{
    0.0050901035f, 0.0050901035f, 0.7136344f, 0.099347f
},
{
    0.0048874947f, 0.0048874947f, 0.71367216f, 0.09938993f
},
{
    0.0047003976f, 0.0047003976f, 0.7137071f, 0.09942958f
},
{
    0.004527097f, 0.004527097f, 0.7137394f, 0.099466294f
},
{
    0.004366121f, 0.004366121f, 0.71376944f, 0.0995004f
},
{
    0.0042161997f, 0.0042161997f, 0.7137974f, 0.09953217f
},
{
    0.0040762327f, 0.0040762327f, 0.71382356f, 0.09956183f
}
};
static const float CORRECTED_NO_BLEND[4] = { 0.0f };
/* The clamp of each state: its map's learning range. */
static const float CORRECTED_LOWER[TWO_TANKS_STATES] = {
    4.3011494f, 4.715646f
};
static const float CORRECTED_UPPER[TWO_TANKS_STATES] = {
    26.20642f, 25.001827f
};

/* One sampling period of the model from x, the value alone: out = x+ (corrected_predict). */
static void corrected_predict(const float *x, const float *u, float *out) {
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = 1.0f;
    const float t3 = 2.0f;
    const float t4 = 6.0f;
    const float t5 = t2 / t3;
    const float t6 = t2 / t4;
    const float t7 = 0.178f /* a1 */;
    const float t8 = 981.0f /* g */;
    const float t9 = t3 * t8;
    const float t10 = fabsf(t0);
    const float t11 = t9 * t10;
    const float t12 = sqrtf(t11);
    const float t13 = t7 * t12;
    const float t14 = 0.178f /* a2 */;
    const float t15 = fabsf(t1);
    const float t16 = t9 * t15;
    const float t17 = sqrtf(t16);
    const float t18 = t14 * t17;
    const float t19 = 3.3f /* k */;
    const float t20 = u[0];
    const float t21 = t19 * t20;
    const float t22 = t21 - t13;
    const float t23 = 15.5f /* A1 */;
    const float t24 = t22 / t23;
    const float t25 = t13 - t18;
    const float t26 = 15.5f /* A2 */;
    const float t27 = t25 / t26;
    const float t28 = t5 * t24;
    const float t29 = t0 + t28;
    const float t30 = t5 * t27;
    const float t31 = t1 + t30;
    const float t32 = fabsf(t29);
    const float t33 = t9 * t32;
    const float t34 = sqrtf(t33);
    const float t35 = t7 * t34;
    const float t36 = fabsf(t31);
    const float t37 = t9 * t36;
    const float t38 = sqrtf(t37);
    const float t39 = t14 * t38;
    const float t40 = t21 - t35;
    const float t41 = t40 / t23;
    const float t42 = t35 - t39;
    const float t43 = t42 / t26;
    const float t44 = t5 * t41;
    const float t45 = t0 + t44;
    const float t46 = t5 * t43;
    const float t47 = t1 + t46;
    const float t48 = fabsf(t45);
    const float t49 = t9 * t48;
    const float t50 = sqrtf(t49);
    const float t51 = t7 * t50;
    const float t52 = fabsf(t47);
    const float t53 = t9 * t52;
    const float t54 = sqrtf(t53);
    const float t55 = t14 * t54;
    const float t56 = t21 - t51;
    const float t57 = t56 / t23;
    const float t58 = t51 - t55;
    const float t59 = t58 / t26;
    const float t60 = t0 + t57;
    const float t61 = t1 + t59;
    const float t62 = fabsf(t60);
    const float t63 = t9 * t62;
    const float t64 = sqrtf(t63);
    const float t65 = t7 * t64;
    const float t66 = fabsf(t61);
    const float t67 = t9 * t66;
    const float t68 = sqrtf(t67);
    const float t69 = t14 * t68;
    const float t70 = t21 - t65;
    const float t71 = t70 / t23;
    const float t72 = t65 - t69;
    const float t73 = t72 / t26;
    const float t74 = t41 + t57;
    const float t75 = t3 * t74;
    const float t76 = t24 + t75;
    const float t77 = t76 + t71;
    const float t78 = t6 * t77;
    const float t79 = t0 + t78;
    const float t80 = t43 + t59;
    const float t81 = t3 * t80;
    const float t82 = t27 + t81;
    const float t83 = t82 + t73;
    const float t84 = t6 * t83;
    const float t85 = t1 + t84;
    out[0] = t79;
    out[1] = t85;
}

/* The correction during the start-up, g = (blends g_j, gains K_j): x before its clamp. */
static void corrected_start_up(const float *x, const float *y, const float *u, const float *f, const float *g, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = y[0];
    const float t3 = t2 - t1;
    const float t4 = g[0];
    const float t5 = f[0];
    const float t6 = t5 - t0;
    const float t7 = t4 * t6;
    const float t8 = t0 + t7;
    const float t9 = g[2];
    const float t10 = t9 * t3;
    const float t11 = t8 + t10;
    const float t12 = g[1];
    const float t13 = f[1];
    const float t14 = t13 - t1;
    const float t15 = t12 * t14;
    const float t16 = t1 + t15;
    const float t17 = g[3];
    const float t18 = t17 * t3;
    const float t19 = t16 + t18;
    out[0] = t11;
    out[1] = t19;
}

/* The correction after the start-up: x before its clamp. */
static void corrected_steady(const float *x, const float *y, const float *u, const float *f, float *out) {
    (void)u;
    (void)f;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = y[0];
    const float t3 = t2 - t1;
    const float t4 = 0.7145841f;
    const float t5 = t4 * t3;
    const float t6 = t0 + t5;
    const float t7 = 0.10042554f;
    const float t8 = t7 * t3;
    const float t9 = t1 + t8;
    out[0] = t6;
    out[1] = t9;
}

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void corrected_map_states(const float *all, float *map) {
    map[0] = all[0];
    map[1] = all[1];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void corrected_targets_of(const float *states, const two_tanks_saturation *state_flags, const float *u,
                                float *values, two_tanks_saturation *flags) {
    targets(states, u, values);
    flags[0] = TWO_TANKS_INSIDE;
    flags[1] = TWO_TANKS_INSIDE;
    flags[0] = state_flags[0];
    flags[1] = state_flags[1];
}

/* Corrector::start: the model's period from the map's first estimate (or from the states after
 * a correction), taken into x when finite. */
static int corrected_start(const float *first, const float *u, float *x) {
    float next[TWO_TANKS_STATES];
    corrected_predict(first, u, next);
    if (!all_finite(next, TWO_TANKS_STATES)) {
        return 0;
    }
    memcpy(x, next, sizeof next);
    return 1;
}

/* Corrector::follow: the correction of the prediction x (the start-up's blend and gain, or
 * G's), clamped to the states' ranges by selects, then the model's period from it. */
static int corrected_follow(float *x, unsigned j, int start_up, const float *f, const float *y, const float *u,
                            float *states, two_tanks_saturation *flags) {
    float raw[TWO_TANKS_STATES];
    unsigned i;
    if (start_up) {
        corrected_start_up(x, y, u, f, (j >= 1u && j <= 30u) ? CORRECTED_BLENDS[j - 1u] : CORRECTED_NO_BLEND, raw);
    } else {
        corrected_steady(x, y, u, f, raw);
    }
    for (i = 0u; i < TWO_TANKS_STATES; ++i) {
        const int low = !(raw[i] >= CORRECTED_LOWER[i]);
        const int out = low | (raw[i] > CORRECTED_UPPER[i]);
        const float edge = select_float(low, CORRECTED_LOWER[i], CORRECTED_UPPER[i]);
        const uint32_t flag = select_bits(low, (uint32_t)TWO_TANKS_LOW, (uint32_t)TWO_TANKS_HIGH);
        states[i] = select_float(out, edge, raw[i]);
        flags[i] = (two_tanks_saturation)select_bits(out, flag, (uint32_t)TWO_TANKS_INSIDE);
    }
    return corrected_start(states, u, x);
}

/* Corrector::predict: a lost output, the model's period from x (no correction). */
static void corrected_lost(float *x, const float *u) {
    (void)corrected_start(x, u, x);
}


static void corrected_fresh(two_tanks_corrected *o) {
    two_tanks_map_init(&o->window);
    memset(o->x, 0, sizeof o->x);
    o->count = 0u;
    o->started = 0;
}

static two_tanks_status corrected_sample(two_tanks_corrected *o, const float *y, const float *u) {
    const int start_up = o->count <= 30u;
    float all[TWO_TANKS_MAP_ROWS], map[TWO_TANKS_STATES], states[TWO_TANKS_STATES];
    two_tanks_saturation all_flags[TWO_TANKS_MAP_ROWS], state_flags[TWO_TANKS_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            corrected_lost(o->x, u);
        }
        return TWO_TANKS_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)two_tanks_map_push(&o->window, y, u);
        if (o->window.filled < TWO_TANKS_HORIZON) {
            return TWO_TANKS_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        corrected_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!corrected_start(map, u, o->x)) {
            corrected_fresh(o);
            return TWO_TANKS_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!corrected_follow(o->x, o->count, start_up, map, y, u, states, state_flags)) {
            corrected_fresh(o);
            return TWO_TANKS_RESTARTED;
        }
        corrected_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return TWO_TANKS_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return TWO_TANKS_OK;
}

void two_tanks_corrected_init(two_tanks_corrected *o) {
    corrected_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

two_tanks_status two_tanks_corrected_push(two_tanks_corrected *o, const float *y, const float *u) {
    const two_tanks_status status = corrected_sample(o, y, u);
    if (status == TWO_TANKS_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == TWO_TANKS_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

two_tanks_status two_tanks_corrected_estimate(const two_tanks_corrected *o, float *values, two_tanks_saturation *saturation) {
    if (!o->ready) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return TWO_TANKS_OK;
}

/* P(N-1)'s upper triangle of the EKF the map starts. */
static const float STARTED_P0[TWO_TANKS_COVARIANCE] = {
    0.38551724f, 0.0f, 0.034644302f
};

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void started_ekf_map_states(const float *all, float *map) {
    map[0] = all[0];
    map[1] = all[1];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void started_ekf_targets_of(const float *states, const two_tanks_saturation *state_flags, const float *u,
                                float *values, two_tanks_saturation *flags) {
    targets(states, u, values);
    flags[0] = TWO_TANKS_INSIDE;
    flags[1] = TWO_TANKS_INSIDE;
    flags[0] = state_flags[0];
    flags[1] = state_flags[1];
}

/* StartedEkf::start: one prediction from the map's states with STARTED_P0, taken when finite;
 * the watched mean at its start. */
static int started_ekf_start(const float *first, const float *u, float *x, float *p, float *chi) {
    float out[TWO_TANKS_STATES + TWO_TANKS_COVARIANCE];
    ekf_unmeasured(first, STARTED_P0, u, out);
    if (!all_finite(out, TWO_TANKS_STATES + TWO_TANKS_COVARIANCE)) {
        return 0;
    }
    memcpy(x, out, TWO_TANKS_STATES * sizeof *x);
    memcpy(p, out + TWO_TANKS_STATES, TWO_TANKS_COVARIANCE * sizeof *p);
    *chi = 1.0f;
    return 1;
}

/* StartedEkf::follow: the EKF's sample, every state inside; not taken when the
 * chi-squared watch (firmware::watch) finds the innovations implausible. */
static int started_ekf_follow(float *x, float *p, float *chi, unsigned j, int start_up, const float *map,
                              const float *y, const float *u, float *states, two_tanks_saturation *flags) {
    unsigned i;
    float nis;
    (void)j;
    (void)start_up;
    (void)map;
    for (i = 0u; i < TWO_TANKS_STATES; ++i) {
        flags[i] = TWO_TANKS_INSIDE;
    }
    if (!ekf_measure(x, p, y, u, states, &nis)) {
        return 0;
    }
    *chi = *chi + 0.1f * (nis - *chi);
    return *chi <= 1024.0f;
}


static void ekf_map_fresh(two_tanks_ekf_map *o) {
    two_tanks_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->count = 0u;
    o->started = 0;
}

static two_tanks_status ekf_map_sample(two_tanks_ekf_map *o, const float *y, const float *u) {
    const int start_up = o->count <= 0u;
    float all[TWO_TANKS_MAP_ROWS], map[TWO_TANKS_STATES], states[TWO_TANKS_STATES];
    two_tanks_saturation all_flags[TWO_TANKS_MAP_ROWS], state_flags[TWO_TANKS_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return TWO_TANKS_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)two_tanks_map_push(&o->window, y, u);
        if (o->window.filled < TWO_TANKS_HORIZON) {
            return TWO_TANKS_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            ekf_map_fresh(o);
            return TWO_TANKS_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!started_ekf_follow(o->x, o->p, &o->chi, o->count, start_up, map, y, u, states, state_flags)) {
            ekf_map_fresh(o);
            return TWO_TANKS_RESTARTED;
        }
        started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return TWO_TANKS_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return TWO_TANKS_OK;
}

void two_tanks_ekf_map_init(two_tanks_ekf_map *o) {
    ekf_map_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

two_tanks_status two_tanks_ekf_map_push(two_tanks_ekf_map *o, const float *y, const float *u) {
    const two_tanks_status status = ekf_map_sample(o, y, u);
    if (status == TWO_TANKS_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == TWO_TANKS_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

two_tanks_status two_tanks_ekf_map_estimate(const two_tanks_ekf_map *o, float *values, two_tanks_saturation *saturation) {
    if (!o->ready) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return TWO_TANKS_OK;
}

/* Whether the filter's prediction x (covariance p) and the map's states f disagree:
 * d = sum_i (x_i - f_i)^2 / (P_ii + e_i^2) > threshold, or d is NaN (restart_disagrees). */
static int restart_disagrees(const float *x, const float *p, const float *f) {
    float d = 0.0f;
    float e;
    e = x[0] - f[0];
    d += e * e / (p[0] + 0.12191126f);
    e = x[1] - f[1];
    d += e * e / (p[2] + 0.010955491f);
    return !(d <= 4.0f);
}

static void ekf_restart_fresh(two_tanks_ekf_restart *o) {
    two_tanks_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

/* firmware::Restarted: the sample to the map's window; from its first estimate on, the map's states
 * against the filter's prediction at every sample, restarted from the map when they disagree;
 * else the filter's sample, restarted (from the map where it has an estimate, else from the start)
 * when its step is not finite or its chi-squared watch finds the innovations implausible. */
static two_tanks_status ekf_restart_sample(two_tanks_ekf_restart *o, const float *y, const float *u) {
    float all[TWO_TANKS_MAP_ROWS], map[TWO_TANKS_STATES], states[TWO_TANKS_STATES];
    two_tanks_saturation all_flags[TWO_TANKS_MAP_ROWS], state_flags[TWO_TANKS_STATES];
    int mapped = 0;
    if (!accepts(y, u)) {
        if (inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return TWO_TANKS_REFUSED;
    }
    (void)two_tanks_map_push(&o->window, y, u);
    if (o->window.filled >= TWO_TANKS_HORIZON) {
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        mapped = 1;
        if (restart_disagrees(o->x, o->p, map) && started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            memcpy(o->values, all, sizeof o->values);
            memcpy(o->flags, all_flags, sizeof o->flags);
            o->ready = 1;
            return TWO_TANKS_OK;
        }
    }
    if (!started_ekf_follow(o->x, o->p, &o->chi, 1u, 0, NULL, y, u, states, state_flags)) {
        if (!(mapped && started_ekf_start(map, u, o->x, o->p, &o->chi))) {
            memcpy(o->x, EKF_X0, sizeof o->x);
            memcpy(o->p, EKF_P0, sizeof o->p);
            o->chi = 1.0f;
        }
        return TWO_TANKS_RESTARTED;
    }
    started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    o->ready = 1;
    return TWO_TANKS_OK;
}

void two_tanks_ekf_restart_init(two_tanks_ekf_restart *o) {
    ekf_restart_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

two_tanks_status two_tanks_ekf_restart_push(two_tanks_ekf_restart *o, const float *y, const float *u) {
    const two_tanks_status status = ekf_restart_sample(o, y, u);
    if (status == TWO_TANKS_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == TWO_TANKS_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

two_tanks_status two_tanks_ekf_restart_estimate(const two_tanks_ekf_restart *o, float *values, two_tanks_saturation *saturation) {
    if (!o->ready) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return TWO_TANKS_OK;
}

/* The model's derivative f(x, u), then its Jacobian row by row (the Rust file's Plant::derivative). */
static void model_derivative(const float *x, const float *u, float *out) {
    const float t0 = 0.178f /* a1 */;
    const float t1 = 2.0f;
    const float t2 = 981.0f /* g */;
    const float t3 = t1 * t2;
    const float t4 = x[0];
    const float t5 = fabsf(t4);
    const float t6 = t3 * t5;
    const float t7 = sqrtf(t6);
    const float t8 = t0 * t7;
    const float t9 = 0.5f;
    const float t10 = t9 / t7;
    const float t11 = signum(t4);
    const float t12 = t3 * t11;
    const float t13 = t10 * t12;
    const float t14 = t0 * t13;
    const float t15 = 0.0f;
    const float t16 = 0.178f /* a2 */;
    const float t17 = x[1];
    const float t18 = fabsf(t17);
    const float t19 = t3 * t18;
    const float t20 = sqrtf(t19);
    const float t21 = t16 * t20;
    const float t22 = t9 / t20;
    const float t23 = signum(t17);
    const float t24 = t3 * t23;
    const float t25 = t22 * t24;
    const float t26 = t16 * t25;
    const float t27 = 3.3f /* k */;
    const float t28 = u[0];
    const float t29 = t27 * t28;
    const float t30 = t29 - t8;
    const float t31 = 15.5f /* A1 */;
    const float t32 = t30 / t31;
    const float t33 = -1.0f;
    const float t34 = t33 / t31;
    const float t35 = t34 * t14;
    const float t36 = t34 * t15;
    const float t37 = t8 - t21;
    const float t38 = 15.5f /* A2 */;
    const float t39 = t37 / t38;
    const float t40 = 1.0f;
    const float t41 = t40 / t38;
    const float t42 = t41 * t14;
    const float t43 = t33 / t38;
    const float t44 = t43 * t15;
    const float t45 = t42 + t44;
    const float t46 = t41 * t15;
    const float t47 = t43 * t26;
    const float t48 = t46 + t47;
    out[0] = t32;
    out[1] = t39;
    out[2] = t35;
    out[3] = t36;
    out[4] = t45;
    out[5] = t48;
}

/* The model's outputs h(x, u), then their Jacobian row by row (the Rust file's Plant::output). */
static void model_output(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = 0.0f;
    const float t1 = x[1];
    const float t2 = 1.0f;
    out[0] = t1;
    out[1] = t0;
    out[2] = t2;
}

/* The moving-horizon estimate's constants: the outputs' weights 1 / sigma^2, the prior's weight per
 * state, the learning box, the first window's start, Levenberg's damping, the RK4 substep. */
static const float MHE_WEIGHTS[TWO_TANKS_OUTPUTS] = {
    25.0f
};
static const float MHE_PRIOR[TWO_TANKS_STATES] = {
    2.0840242f, 2.4299614f
};
static const float MHE_LOWER[TWO_TANKS_STATES] = {
    4.3011494f, 4.715646f
};
static const float MHE_UPPER[TWO_TANKS_STATES] = {
    26.20642f, 25.001827f
};
static const float MHE_START[TWO_TANKS_STATES] = {
    15.0f, 15.0f
};
static const float MHE_DAMPING = 1e-6f;
static const float MHE_H = 1.0f;
/* The chi-square watch over the windows' output costs (firmware::watch): the mean's start N m, its
 * gain 1 / W and its limit tau N m. */
static const float MHE_WATCH_START = 10.0f;
static const float MHE_WATCH_GAIN = 0.1f;
static const float MHE_WATCH_LIMIT = 10240.0f;
#define MHE_ITERATIONS 2u
#define MHE_SUBSTEPS 1u
#define MHE_NX TWO_TANKS_STATES
#define MHE_NY TWO_TANKS_OUTPUTS
/* The inputs of the window's sample k (oldest first) of the observer o. */
#define MHE_U(o, k) (o)->u[(o)->next + (k)]

/* firmware::matrix::product: out = a b, each entry summed from 0 in k's order. */
static void mhe_product(float (*a)[MHE_NX], float (*b)[MHE_NX], float (*out)[MHE_NX]) {
    unsigned r, c, k;
    for (r = 0u; r < MHE_NX; ++r) {
        for (c = 0u; c < MHE_NX; ++c) {
            float entry = 0.0f;
            for (k = 0u; k < MHE_NX; ++k) {
                entry += a[r][k] * b[k][c];
            }
            out[r][c] = entry;
        }
    }
}

/* The derivative k and its Jacobian d at x. */
static void mhe_derivative(const float *x, const float *u, float *k, float (*d)[MHE_NX]) {
    float out[MHE_NX + MHE_NX * MHE_NX];
    unsigned i, j;
    model_derivative(x, u, out);
    for (i = 0u; i < MHE_NX; ++i) {
        k[i] = out[i];
        for (j = 0u; j < MHE_NX; ++j) {
            d[i][j] = out[MHE_NX + i * MHE_NX + j];
        }
    }
}

/* Rk4::stage: the derivative at x + w k, and its Jacobian times (I + w d). */
static void mhe_stage(const float *x, const float *k, float (*d)[MHE_NX], float w, const float *u, float *value,
                      float (*jacobian)[MHE_NX]) {
    float point[MHE_NX];
    float moved[MHE_NX][MHE_NX], a[MHE_NX][MHE_NX];
    unsigned i, j;
    for (i = 0u; i < MHE_NX; ++i) {
        point[i] = x[i] + w * k[i];
        for (j = 0u; j < MHE_NX; ++j) {
            moved[i][j] = (i == j ? 1.0f : 0.0f) + w * d[i][j];
        }
    }
    mhe_derivative(point, u, value, a);
    mhe_product(a, moved, jacobian);
}

/* Rk4::substep: one classical RK4 step of MHE_H from x, with its Jacobian. */
static void mhe_substep(const float *x, const float *u, float *next, float (*jacobian)[MHE_NX]) {
    const float two = 1.0f + 1.0f;
    const float half = MHE_H / two;
    const float sixth = MHE_H / (two + two + two);
    float k1[MHE_NX], k2[MHE_NX], k3[MHE_NX], k4[MHE_NX];
    float d1[MHE_NX][MHE_NX], d2[MHE_NX][MHE_NX], d3[MHE_NX][MHE_NX], d4[MHE_NX][MHE_NX];
    unsigned i, j;
    mhe_derivative(x, u, k1, d1);
    mhe_stage(x, k1, d1, half, u, k2, d2);
    mhe_stage(x, k2, d2, half, u, k3, d3);
    mhe_stage(x, k3, d3, MHE_H, u, k4, d4);
    for (i = 0u; i < MHE_NX; ++i) {
        next[i] = x[i] + sixth * (k1[i] + two * (k2[i] + k3[i]) + k4[i]);
        for (j = 0u; j < MHE_NX; ++j) {
            jacobian[i][j] = (i == j ? 1.0f : 0.0f) + sixth * (d1[i][j] + two * (d2[i][j] + d3[i][j]) + d4[i][j]);
        }
    }
}

/* Rk4::step: one sampling period (MHE_SUBSTEPS substeps, their Jacobians composed). */
static void mhe_step(const float *x, const float *u, float *next, float (*jacobian)[MHE_NX]) {
    unsigned s;
    mhe_substep(x, u, next, jacobian);
    for (s = 1u; s < MHE_SUBSTEPS; ++s) {
        float from[MHE_NX];
        float d[MHE_NX][MHE_NX], composed[MHE_NX][MHE_NX];
        memcpy(from, next, sizeof from);
        mhe_substep(from, u, next, d);
        mhe_product(d, jacobian, composed);
        memcpy(jacobian, composed, sizeof composed);
    }
}

/* firmware::bounds::project onto the learning box: at_least, then at_most, by selects. */
static void mhe_project(const float *x, float *out) {
    unsigned i;
    for (i = 0u; i < MHE_NX; ++i) {
        const float above = select_float(!(x[i] >= MHE_LOWER[i]), MHE_LOWER[i], x[i]);
        out[i] = select_float(above > MHE_UPPER[i], MHE_UPPER[i], above);
    }
}

/* firmware::mhe::normal_equations over the window of o from x: J^T W J and J^T W r (a non-finite
 * residual weighs nothing). */
static void mhe_normal(const two_tanks_mhe *o, const float *x, float (*matrix)[MHE_NX], float *gradient, float *cost) {
    float state[MHE_NX];
    float sensitivity[MHE_NX][MHE_NX];
    unsigned k, i, a, b, c, m;
    memcpy(state, x, sizeof state);
    *cost = 0.0f;
    for (a = 0u; a < MHE_NX; ++a) {
        gradient[a] = 0.0f;
        for (b = 0u; b < MHE_NX; ++b) {
            matrix[a][b] = 0.0f;
            sensitivity[a][b] = a == b ? 1.0f : 0.0f;
        }
    }
    for (k = 0u; k < TWO_TANKS_HORIZON; ++k) {
        const float *y = o->y[o->next + k];
        float out[MHE_NY + MHE_NY * MHE_NX];
        if (k > 0u) {
            float next[MHE_NX];
            float f[MHE_NX][MHE_NX], composed[MHE_NX][MHE_NX];
            mhe_step(state, MHE_U(o, k - 1u), next, f);
            memcpy(state, next, sizeof state);
            mhe_product(f, sensitivity, composed);
            memcpy(sensitivity, composed, sizeof composed);
        }
        model_output(state, MHE_U(o, k), out);
        for (i = 0u; i < MHE_NY; ++i) {
            const float raw = y[i] - out[i];
            const int finite = is_finite(raw);
            const float residual = select_float(finite, raw, 0.0f);
            const float w = select_float(finite, MHE_WEIGHTS[i], 0.0f);
            float row[MHE_NX];
            *cost += w * residual * residual;
            for (c = 0u; c < MHE_NX; ++c) {
                row[c] = 0.0f;
                for (m = 0u; m < MHE_NX; ++m) {
                    row[c] += out[MHE_NY + i * MHE_NX + m] * sensitivity[m][c];
                }
            }
            for (a = 0u; a < MHE_NX; ++a) {
                const float weighted = w * row[a];
                gradient[a] += weighted * residual;
                for (b = 0u; b < MHE_NX; ++b) {
                    matrix[a][b] += weighted * row[b];
                }
            }
        }
    }
}

/* firmware::mhe::solve_cholesky: a x = b by a = L D L^T (no square root); 0 where a pivot is not
 * positive and finite. */
static int mhe_cholesky(float (*a)[MHE_NX], const float *b, float *x) {
    float l[MHE_NX][MHE_NX], d[MHE_NX], inverse_d[MHE_NX], z[MHE_NX];
    unsigned i, j, k, r;
    memset(l, 0, sizeof l);
    for (j = 0u; j < MHE_NX; ++j) {
        float pivot = a[j][j];
        for (k = 0u; k < j; ++k) {
            pivot -= l[j][k] * l[j][k] * d[k];
        }
        if (!(pivot > 0.0f) || !is_finite(pivot)) {
            return 0;
        }
        d[j] = pivot;
        inverse_d[j] = 1.0f / pivot;
        for (i = j + 1u; i < MHE_NX; ++i) {
            float sum = a[i][j];
            /* k < MHE_NX always holds: said for gcc -O1, which otherwise warns of an access beyond l. */
            for (k = 0u; k < j && k < MHE_NX; ++k) {
                sum -= l[i][k] * l[j][k] * d[k];
            }
            l[i][j] = sum * inverse_d[j];
        }
    }
    for (r = 0u; r < MHE_NX; ++r) {
        float sum = b[r];
        for (k = 0u; k < r; ++k) {
            sum -= l[r][k] * z[k];
        }
        z[r] = sum;
    }
    for (r = MHE_NX; r-- > 0u;) {
        float sum = z[r] * inverse_d[r];
        for (k = r + 1u; k < MHE_NX; ++k) {
            sum -= l[k][r] * x[k];
        }
        x[r] = sum;
    }
    return 1;
}

/* firmware::mhe::solve_window: MHE_ITERATIONS damped Gauss-Newton steps from centre (with the prior
 * around it when `prior`), each projected; the solution x, the state at the newest sample and the
 * window's output cost at the last step's start. */
static void mhe_solve_window(const two_tanks_mhe *o, const float *centre, int prior, float *solution, float *end, float *cost) {
    float x[MHE_NX], state[MHE_NX];
    unsigned n, i, k;
    memcpy(x, centre, sizeof x);
    *cost = 0.0f;
    for (n = 0u; n < MHE_ITERATIONS; ++n) {
        float matrix[MHE_NX][MHE_NX];
        float gradient[MHE_NX], step[MHE_NX], next[MHE_NX];
        mhe_normal(o, x, matrix, gradient, cost);
        for (i = 0u; i < MHE_NX; ++i) {
            if (prior) {
                matrix[i][i] += MHE_PRIOR[i];
                gradient[i] -= MHE_PRIOR[i] * (x[i] - centre[i]);
            }
            matrix[i][i] += MHE_DAMPING * matrix[i][i];
        }
        if (!mhe_cholesky(matrix, gradient, step)) {
            break;
        }
        for (i = 0u; i < MHE_NX; ++i) {
            next[i] = x[i] + step[i];
        }
        mhe_project(next, x);
    }
    memcpy(solution, x, sizeof x);
    memcpy(state, x, sizeof state);
    for (k = 1u; k < TWO_TANKS_HORIZON; ++k) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(state, MHE_U(o, k - 1u), next, f);
        memcpy(state, next, sizeof state);
    }
    mhe_project(state, end);
}

void two_tanks_mhe_init(two_tanks_mhe *o) {
    o->next = 0u;
    o->filled = 0u;
    o->has_solved = 0;
    o->ready = 0;
    o->restarts = 0u;
    o->chi = 0.0f;
    o->has_chi = 0;
}

two_tanks_status two_tanks_mhe_push(two_tanks_mhe *o, const float *y, const float *u) {
    float moved[MHE_NX], x[MHE_NX], end[MHE_NX], values[TWO_TANKS_TARGETS], cost;
    int has_moved = 0;
    unsigned i, slot;
    float chi;
    if (!all_finite(y, TWO_TANKS_OUTPUTS) || !inputs_finite(u)) {
        return TWO_TANKS_REFUSED;
    }
    /* The previous solution moved one sample on: the prior's centre and the first iterate. */
    if (o->has_solved && o->filled >= TWO_TANKS_HORIZON) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(o->solved, MHE_U(o, 0u), next, f);
        mhe_project(next, moved);
        has_moved = 1;
    }
    /* Every value of the sample is finite: stored. */
    slot = o->next;
    for (i = 0u; i < TWO_TANKS_OUTPUTS; ++i) {
        o->y[slot][i] = y[i];
        o->y[slot + TWO_TANKS_HORIZON][i] = y[i];
    }
    for (i = 0u; i < TWO_TANKS_INPUTS; ++i) {
        o->u[slot][i] = u[i];
        o->u[slot + TWO_TANKS_HORIZON][i] = u[i];
    }
    o->next = slot + 1u >= TWO_TANKS_HORIZON ? 0u : slot + 1u;
    o->filled += (unsigned)(o->filled < TWO_TANKS_HORIZON);
    if (o->filled < TWO_TANKS_HORIZON) {
        return TWO_TANKS_OK;
    }
    mhe_solve_window(o, has_moved ? moved : MHE_START, has_moved, x, end, &cost);
    targets(end, u, values);
    /* firmware::watch: the windows' costs' mean, from its start after a (re)start. */
    chi = o->has_chi ? o->chi : MHE_WATCH_START;
    chi = chi + MHE_WATCH_GAIN * (cost - chi);
    if (!all_finite(x, MHE_NX) || !all_finite(end, MHE_NX) || !all_finite(values, TWO_TANKS_TARGETS)
        || !(chi <= MHE_WATCH_LIMIT)) {
        /* Restarted: the next window is solved from the start, not from this solution. */
        o->has_chi = 0;
        o->has_solved = 0;
        if (o->restarts != UINT32_MAX) {
            ++o->restarts;
        }
        return TWO_TANKS_RESTARTED;
    }
    memcpy(o->solved, x, sizeof x);
    o->has_solved = 1;
    o->chi = chi;
    o->has_chi = 1;
    memcpy(o->values, values, sizeof values);
    for (i = 0u; i < TWO_TANKS_TARGETS; ++i) {
        o->flags[i] = TWO_TANKS_INSIDE;
    }
    o->ready = 1;
    return TWO_TANKS_OK;
}

#undef MHE_ITERATIONS
#undef MHE_SUBSTEPS
#undef MHE_NX
#undef MHE_NY
#undef MHE_U

two_tanks_status two_tanks_mhe_estimate(const two_tanks_mhe *o, float *values, two_tanks_saturation *saturation) {
    if (!o->ready) {
        return TWO_TANKS_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return TWO_TANKS_OK;
}

/* The mark of this design's observer in storage (never 0: zeroed storage holds none). */
#define STORAGE_MARK 0x491c647d9c035b4bull

/* The observer in storage: TWO_TANKS_BAD_ARGUMENT for a null or misaligned pointer,
 * TWO_TANKS_NOT_INITIALISED where two_tanks_init did not make one (it reads the first 16 bytes only). */
static two_tanks_status stored_observer(void *storage, two_tanks_observer **observer) {
    two_tanks_stored *stored = (two_tanks_stored *)storage;
    if (storage == NULL || (uintptr_t)storage % TWO_TANKS_STORAGE_ALIGN != 0u) {
        return TWO_TANKS_BAD_ARGUMENT;
    }
    if (stored->mark != STORAGE_MARK || stored->size < (uint64_t)sizeof(two_tanks_stored)) {
        return TWO_TANKS_NOT_INITIALISED;
    }
    *observer = &stored->observer;
    return TWO_TANKS_OK;
}

two_tanks_status two_tanks_init(void *storage, size_t size) {
    two_tanks_stored *stored = (two_tanks_stored *)storage;
    if (storage == NULL || size < sizeof(two_tanks_stored) || (uintptr_t)storage % TWO_TANKS_STORAGE_ALIGN != 0u) {
        return TWO_TANKS_BAD_ARGUMENT;
    }
    stored->mark = STORAGE_MARK;
    stored->size = (uint64_t)size;
    two_tanks_observer_init(&stored->observer);
    return TWO_TANKS_OK;
}

two_tanks_status two_tanks_push(void *storage, const float *y, const float *u) {
    two_tanks_observer *observer = NULL;
    const two_tanks_status found = stored_observer(storage, &observer);
    if (found != TWO_TANKS_OK) {
        return found;
    }
    if (y == NULL || u == NULL) {
        return TWO_TANKS_BAD_ARGUMENT;
    }
    return two_tanks_observer_push(observer, y, u);
}

two_tanks_status two_tanks_estimate(void *storage, float *estimates, two_tanks_saturation *saturation) {
    two_tanks_observer *observer = NULL;
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    const two_tanks_status found = stored_observer(storage, &observer);
    if (found != TWO_TANKS_OK) {
        return found;
    }
    if (estimates == NULL) {
        return TWO_TANKS_BAD_ARGUMENT;
    }
    return two_tanks_observer_estimate(observer, estimates, saturation != NULL ? saturation : flags);
}

size_t two_tanks_storage_size(void) {
    return sizeof(two_tanks_stored);
}

#undef STORAGE_MARK
