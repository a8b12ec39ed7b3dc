<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="cow.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0.491455" y="0.174994" z="9.82235e-005" active="1" name="nose_tip"/>
 <point x="0.435383" y="0.124924" z="6.31791e-005" active="1" name="chin"/>
 <point x="0.352247" y="0.283606" z="-5.77525e-005" active="1" name="head_top"/>
 <point x="0.394649" y="0.228406" z="-0.0601362" active="1" name="left_eye"/>
 <point x="0.394649" y="0.228406" z="0.0601362" active="1" name="right_eye"/>
 <point x="0.313153" y="0.266184" z="-0.139079" active="1" name="left_ear_tip"/>
 <point x="0.313153" y="0.266184" z="0.139079" active="1" name="right_ear_tip"/>
 <point x="0.41364" y="0.306243" z="-0.07418" active="1" name="left_horn_tip"/>
 <point x="0.41364" y="0.306243" z="0.07418" active="1" name="right_horn_tip"/>
 <point x="0.256498" y="0.249766" z="-1.55991e-008" active="1" name="neck_top"/>
 <point x="0.282993" y="0.059848" z="-1.55991e-008" active="1" name="neck_bottom"/>
 <point x="0.129454" y="0.213239" z="-1.55991e-008" active="1" name="withers"/>
 <point x="-0.0962309" y="0.208056" z="-1.55991e-008" active="1" name="mid_back"/>
 <point x="-0.326084" y="0.225668" z="-1.55991e-008" active="1" name="rump"/>
 <point x="-0.445356" y="0.183744" z="-1.55991e-008" active="1" name="tail_base"/>
 <point x="-0.5" y="-0.150946" z="0.0181639" active="1" name="tail_tip"/>
 <point x="0.224245" y="-0.0253995" z="-1.55991e-008" active="1" name="chest"/>
 <point x="0.0144936" y="-0.107223" z="-1.55991e-008" active="1" name="belly"/>
 <point x="-0.125399" y="-0.013752" z="-0.162908" active="1" name="left_flank"/>
 <point x="-0.125399" y="-0.013752" z="0.162908" active="1" name="right_flank"/>
 <point x="0.112136" y="-0.191937" z="-0.0701446" active="1" name="left_front_knee"/>
 <point x="0.112136" y="-0.191937" z="0.0701446" active="1" name="right_front_knee"/>
 <point x="-0.409295" y="-0.126717" z="-0.0730063" active="1" name="left_hind_knee"/>
 <point x="-0.409295" y="-0.126717" z="0.0730063" active="1" name="right_hind_knee"/>
 <point x="0.136137" y="-0.30116" z="-0.0896634" active="1" name="left_front_hoof"/>
 <point x="0.136137" y="-0.30116" z="0.0896634" active="1" name="right_front_hoof"/>
 <point x="-0.341623" y="-0.306143" z="-0.103271" active="1" name="left_hind_hoof"/>
 <point x="-0.341623" y="-0.306143" z="0.103271" active="1" name="right_hind_hoof"/>
</PickedPoints>
