<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="diplodocus.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0.5" y="0.373614" z="0.102367" active="1" name="nose_tip"/>
 <point x="0.461273" y="0.370887" z="0.102598" active="1" name="chin"/>
 <point x="0.444185" y="0.467169" z="0.112683" active="1" name="head_top"/>
 <point x="0.428221" y="0.418858" z="0.0693726" active="1" name="left_cheek"/>
 <point x="0.421334" y="0.417971" z="0.152828" active="1" name="right_cheek"/>
 <point x="0.315926" y="0.411933" z="0.098183" active="1" name="nape"/>
 <point x="0.251419" y="0.20607" z="0.0804909" active="1" name="neck_mid"/>
 <point x="0.28536" y="-0.0844774" z="0.0130721" active="1" name="neck_bottom"/>
 <point x="0.143213" y="0.0548866" z="0.0397151" active="1" name="withers"/>
 <point x="-0.0304983" y="0.0501129" z="0.0403434" active="1" name="mid_back"/>
 <point x="-0.171206" y="0.0234907" z="-0.00820197" active="1" name="rump"/>
 <point x="-0.295879" y="-0.0540693" z="-0.0174046" active="1" name="tail_base"/>
 <point x="-0.498708" y="-0.344279" z="-0.015983" active="1" name="tail_tip"/>
 <point x="0.188609" y="-0.173303" z="0.000729217" active="1" name="chest"/>
 <point x="-0.0243493" y="-0.189921" z="0.0178663" active="1" name="belly"/>
 <point x="-0.0272867" y="-0.074737" z="-0.088538" active="1" name="left_flank"/>
 <point x="-0.0119251" y="-0.0746748" z="0.133519" active="1" name="right_flank"/>
 <point x="0.176686" y="-0.287908" z="-0.0645181" active="1" name="left_front_knee"/>
 <point x="0.199519" y="-0.321521" z="0.116827" active="1" name="right_front_knee"/>
 <point x="-0.186368" y="-0.255804" z="-0.106866" active="1" name="left_hind_knee"/>
 <point x="-0.0770937" y="-0.282281" z="0.0915344" active="1" name="right_hind_knee"/>
 <point x="0.217292" y="-0.417623" z="-0.076737" active="1" name="left_front_foot"/>
 <point x="0.263188" y="-0.456722" z="0.114765" active="1" name="right_front_foot"/>
 <point x="-0.211207" y="-0.361051" z="-0.116352" active="1" name="left_hind_foot"/>
 <point x="-0.0720354" y="-0.413111" z="0.0597658" active="1" name="right_hind_foot"/>
</PickedPoints>
